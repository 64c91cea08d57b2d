#include "pr2_configurations.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "opx_pipelines.hpp"
#include "pr2_fcl.hpp"
#include "rng.hpp"
#include "scene.hpp"

namespace paper_tables {
namespace {

constexpr int kArmJoints = 14;
const char *const kJointNames[kArmJoints] = {
    "r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint", "r_elbow_flex_joint",
    "r_forearm_roll_joint", "r_wrist_flex_joint",    "r_wrist_roll_joint",     "l_shoulder_pan_joint",
    "l_shoulder_lift_joint", "l_upper_arm_roll_joint", "l_elbow_flex_joint",   "l_forearm_roll_joint",
    "l_wrist_flex_joint",    "l_wrist_roll_joint"};
// Both arms stretched forward (the right one as opx-demo --real's goal, the
// left one its mirror image), reaching over the sensed surface.
const double kReach[kArmJoints] = {-0.1, 0.1, 0.0, -0.35, 0.0, -0.4, 0.0, 0.1, 0.1, 0.0, -0.35, 0.0, -0.4, 0.0};
constexpr double kSpread = 0.5;             // rad: each joint uniform in reach +- this
constexpr double kMinPenetration = 0.015;   // m: collision set window
constexpr double kMaxPenetration = 0.05;
constexpr double kMinDistance = 0.01;       // m: distance set window
constexpr double kMaxDistance = 0.055;
constexpr int kMaxDrawsPerConfiguration = 200;
constexpr uint64_t kSeed = 0x7AB1E4u;

struct ArmJoint {
    uint32_t index;
    double lower, upper;
};

std::vector<ArmJoint> arm_joints(const opx_linkset *robot) {
    std::vector<ArmJoint> joints;
    for (const char *name : kJointNames) {
        ArmJoint joint{0, -INFINITY, INFINITY};
        check_opx(opx_linkset_find_joint(robot, name, &joint.index), "opx_linkset_find_joint");
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        check_opx(opx_linkset_joint_info(robot, joint.index, &info), "opx_linkset_joint_info");
        if (info.has_limits && info.type != OPX_JOINT_CONTINUOUS) joint.lower = info.lower, joint.upper = info.upper;
        joints.push_back(joint);
    }
    return joints;
}

std::vector<double> joint_positions(const opx_linkset *robot) {
    size_t count = 0;
    opx_linkset_get_joint_positions(robot, nullptr, 0, &count);  // BUFFER_TOO_SMALL gives the count
    std::vector<double> positions(count);
    check_opx(opx_linkset_get_joint_positions(robot, positions.data(), count, &count),
              "opx_linkset_get_joint_positions");
    return positions;
}

double signed_distance(opx_query *query, const opx_octree *tree, const opx_linkset *robot) {
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.signed_distance = 1;
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    check_opx(opx_query_distance(query, tree, robot, &request, &result), "opx_query_distance (signed)");
    return result.distance;
}

double mean_of(const std::vector<Configuration> &set, double sign) {
    double sum = 0.0;
    for (const Configuration &c : set) sum += sign * c.signed_distance;
    return set.empty() ? 0.0 : sum / set.size();
}

void print_sets(const ConfigurationSets &sets, int count) {
    std::printf("configurations: both arms reach forward into the scene (joints uniform within +-%.2f rad of the "
                "reaching pose, clamped to the URDF limits; seed 0x%llx); %d candidates drawn; OctoProx's signed "
                "distance sorts them:\n",
                kSpread, static_cast<unsigned long long>(kSeed), sets.drawn);
    std::printf("  collision set: %zu of %d configurations with a penetration depth in [%.1f, %.1f] cm: average "
                "%.2f cm (paper: 2.8 cm)\n",
                sets.collision.size(), count, kMinPenetration * 100, kMaxPenetration * 100,
                mean_of(sets.collision, -1.0) * 100);
    std::printf("  distance set:  %zu of %d collision-free configurations with a distance in [%.1f, %.1f] cm: "
                "average %.2f cm (paper: 3.4 cm)\n",
                sets.distance.size(), count, kMinDistance * 100, kMaxDistance * 100,
                mean_of(sets.distance, 1.0) * 100);
    if (static_cast<int>(sets.collision.size()) < count || static_cast<int>(sets.distance.size()) < count)
        std::printf("  WARNING: fewer configurations than asked for after %d draws\n", sets.drawn);
}

}  // namespace

ConfigurationSets choose_configurations(opx_linkset *robot, const opx_octree *tree, int count) {
    const std::vector<ArmJoint> joints = arm_joints(robot);
    const std::vector<double> start = joint_positions(robot);
    const OpxQueryPtr query = make_direct_query();
    Rng rng(kSeed);
    ConfigurationSets sets;
    const auto full = [&](const std::vector<Configuration> &set) { return static_cast<int>(set.size()) >= count; };
    while ((!full(sets.collision) || !full(sets.distance)) && sets.drawn < kMaxDrawsPerConfiguration * count) {
        Configuration c;
        c.joints = start;
        for (int j = 0; j < kArmJoints; ++j)
            c.joints[joints[j].index] =
                std::clamp(kReach[j] + rng.uniform(-kSpread, kSpread), joints[j].lower, joints[j].upper);
        ++sets.drawn;
        check_opx(opx_linkset_set_joint_positions(robot, c.joints.data(), c.joints.size(), nullptr),
                  "opx_linkset_set_joint_positions");
        c.signed_distance = signed_distance(query.get(), tree, robot);
        const double d = c.signed_distance;
        if (d <= -kMinPenetration && d >= -kMaxPenetration && !full(sets.collision)) {
            c.poses = link_poses(robot);
            sets.collision.push_back(std::move(c));
        } else if (d >= kMinDistance && d <= kMaxDistance && !full(sets.distance)) {
            c.poses = link_poses(robot);
            sets.distance.push_back(std::move(c));
        }
    }
    check_opx(opx_linkset_set_joint_positions(robot, start.data(), start.size(), nullptr),
              "opx_linkset_set_joint_positions");
    print_sets(sets, count);
    return sets;
}

void apply_configuration(opx_linkset *robot, const Configuration &configuration) {
    check_opx(opx_linkset_set_poses(robot, configuration.poses.data(), configuration.poses.size(), 0),
              "opx_linkset_set_poses");
}

}  // namespace paper_tables
