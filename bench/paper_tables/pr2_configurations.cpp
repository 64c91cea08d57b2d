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
// Both arms stretched forward (the right one in the reaching pose of
// opx-demo --real, the left one its mirror image), reaching over the
// sensed surface.
const double kReach[kArmJoints] = {-0.1, 0.1, 0.0, -0.35, 0.0, -0.4, 0.0, 0.1, 0.1, 0.0, -0.35, 0.0, -0.4, 0.0};
constexpr double kSpread = 0.5;             // rad: each joint uniform in reach +- this
constexpr double kMinPenetration = 0.01;    // m: collision set window (lift depth)
constexpr double kMaxPenetration = 0.05;
constexpr int kBisections = 12;             // lift depth to 0.05 / 2^12 m
constexpr double kMinDistance = 0.01;       // m: distance set window
constexpr double kMaxDistance = 0.06;
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
        check_opx(opx_linkset_get_joint_info(robot, joint.index, &info), "opx_linkset_get_joint_info");
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

void forward_kinematics(opx_linkset *robot, const std::vector<double> &joints, const opx_pose &base) {
    check_opx(opx_linkset_set_joint_positions(robot, joints.data(), joints.size(), &base),
              "opx_linkset_set_joint_positions");
}

void forward_kinematics(opx_linkset *robot, const std::vector<double> &joints, double lift) {
    opx_pose base = OPX_POSE_IDENTITY;
    base.position[2] = lift;
    forward_kinematics(robot, joints, base);
}

// `start` with each arm joint uniform within +-kSpread of the reaching pose,
// clamped to its limits.
std::vector<double> draw_reaching_joints(const std::vector<ArmJoint> &joints, const std::vector<double> &start,
                                         Rng &rng) {
    std::vector<double> drawn = start;
    for (int j = 0; j < kArmJoints; ++j)
        drawn[joints[j].index] = std::clamp(kReach[j] + rng.uniform(-kSpread, kSpread), joints[j].lower, joints[j].upper);
    return drawn;
}

// The smallest lift in [0, kMaxPenetration] found by bisection after which
// the robot is clear; +infinity when still colliding at kMaxPenetration.
double lift_depth(opx_query *query, const opx_octree *tree, opx_linkset *robot, const std::vector<double> &joints) {
    double colliding = 0.0, clear = kMaxPenetration;
    forward_kinematics(robot, joints, clear);
    if (opx_collides(query, tree, robot)) return INFINITY;
    for (int i = 0; i < kBisections; ++i) {
        const double middle = 0.5 * (colliding + clear);
        forward_kinematics(robot, joints, middle);
        (opx_collides(query, tree, robot) ? colliding : clear) = middle;
    }
    return clear;
}

double mean_of(const std::vector<Configuration> &set, double Configuration::*field, double sign) {
    double sum = 0.0;
    for (const Configuration &c : set) sum += sign * (c.*field);
    return set.empty() ? 0.0 : sum / set.size();
}

void print_sets(const ConfigurationSets &sets, int count) {
    std::printf("configurations: both arms reach forward into the scene (joints uniform within +-%.2f rad of the "
                "reaching pose, clamped to the URDF limits; seed 0x%llx); %d candidates drawn; OctoProx (direct) "
                "sorts them:\n",
                kSpread, static_cast<unsigned long long>(kSeed), sets.drawn);
    std::printf("  collision set: %zu of %d colliding configurations with a penetration depth (the lift along +z "
                "that clears the robot, bisection) in [%.1f, %.1f] cm: average %.2f cm (paper: 2.8 cm); the "
                "library's deepest EPA depth per configuration (signed distance): average %.2f cm (per shape-cell "
                "pair: bounded by about a cell for the arms' surface meshes)\n",
                sets.collision.size(), count, kMinPenetration * 100, kMaxPenetration * 100,
                mean_of(sets.collision, &Configuration::lift_depth, 1.0) * 100,
                mean_of(sets.collision, &Configuration::signed_distance, -1.0) * 100);
    std::printf("  distance set:  %zu of %d collision-free configurations with a distance in [%.1f, %.1f] cm: "
                "average %.2f cm (paper: 3.4 cm)\n",
                sets.distance.size(), count, kMinDistance * 100, kMaxDistance * 100,
                mean_of(sets.distance, &Configuration::signed_distance, 1.0) * 100);
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
        c.joints = draw_reaching_joints(joints, start, rng);
        ++sets.drawn;
        forward_kinematics(robot, c.joints, 0.0);
        if (opx_collides(query.get(), tree, robot)) {
            if (full(sets.collision)) continue;
            c.lift_depth = lift_depth(query.get(), tree, robot, c.joints);
            if (c.lift_depth < kMinPenetration || c.lift_depth > kMaxPenetration) continue;
            forward_kinematics(robot, c.joints, 0.0);
            c.signed_distance = signed_distance(query.get(), tree, robot);
            c.poses = link_poses(robot);
            sets.collision.push_back(std::move(c));
        } else if (!full(sets.distance)) {
            c.signed_distance = signed_distance(query.get(), tree, robot);
            if (c.signed_distance < kMinDistance || c.signed_distance > kMaxDistance) continue;
            c.poses = link_poses(robot);
            sets.distance.push_back(std::move(c));
        }
    }
    forward_kinematics(robot, start, 0.0);
    print_sets(sets, count);
    std::fflush(stdout);
    return sets;
}

std::vector<Configuration> draw_reaching_configurations(opx_linkset *robot, int count, uint64_t seed,
                                                        const opx_pose &base) {
    const std::vector<ArmJoint> joints = arm_joints(robot);
    const std::vector<double> start = joint_positions(robot);
    Rng rng(seed);
    std::vector<Configuration> drawn(count);
    for (Configuration &c : drawn) {
        c.joints = draw_reaching_joints(joints, start, rng);
        forward_kinematics(robot, c.joints, base);
        c.poses = link_poses(robot);
    }
    forward_kinematics(robot, start, 0.0);
    return drawn;
}

void apply_configuration(opx_linkset *robot, const Configuration &configuration) {
    check_opx(opx_linkset_set_poses(robot, configuration.poses.data(), configuration.poses.size(), 0),
              "opx_linkset_set_poses");
}

}  // namespace paper_tables
