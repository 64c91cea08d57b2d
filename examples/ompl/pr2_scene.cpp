#include "pr2_scene.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sys/stat.h>

namespace opx_ompl {

const char *const kArmJointNames[kArmJoints] = {
    "r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint", "r_elbow_flex_joint",
    "r_forearm_roll_joint", "r_wrist_flex_joint",    "r_wrist_roll_joint"};

namespace {

constexpr const char *kFrame = "rgbd/frame_20121214T142255.814212_binary.pcd";
constexpr const char *kUrdf = "robots/pr2_description/urdf/robot.xml";
constexpr const char *kSrdf = "robots/pr2_description/srdf/pr2.srdf";
constexpr const char *kCamera = "wide_stereo_optical_frame";

// The joints that stay still: the head tilted down 0.82 rad (the frame's
// large flat surface then lies level), the left arm held out to the left,
// clear of the right arm's tucked pose.
const char *const kStillJoints[3] = {"head_tilt_joint", "l_shoulder_pan_joint", "l_elbow_flex_joint"};
const double kStillPositions[3] = {0.82, 1.5, -0.3};

bool ok(opx_status status, const char *what) {
    if (status == OPX_OK) return true;
    std::fprintf(stderr, "opx-ompl-plan: %s: %s\n", what, opx_last_error());
    return false;
}

bool exists(const std::string &path) {
    struct stat info;
    return stat(path.c_str(), &info) == 0;
}

bool load_robot(const std::string &data, Pr2Scene &s) {
    const std::string urdf = data + "/" + kUrdf, srdf = data + "/" + kSrdf;
    const std::string package = "moveit_resources_pr2_description=" + data + "/robots/pr2_description";
    const char *dirs[1] = {package.c_str()};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    options.srdf_path = srdf.c_str();
    if (!ok(opx_linkset_load_urdf_file(urdf.c_str(), &options, &s.robot), "opx_linkset_load_urdf_file")) return false;
    return ok(opx_linkset_set_named_joint_positions(s.robot, kStillJoints, kStillPositions, 3, nullptr),
              "opx_linkset_set_named_joint_positions");
}

// The frame as the head camera sees it, the robot's own points left out.
bool load_map(const std::string &data, double resolution, Pr2Scene &s) {
    opx_point_cloud *cloud = nullptr;
    opx_point_cloud_info info = OPX_POINT_CLOUD_INFO_INIT;
    if (!ok(opx_point_cloud_read_file((data + "/" + kFrame).c_str(), &cloud), "opx_point_cloud_read_file") ||
        !ok(opx_point_cloud_get_info(cloud, &info), "opx_point_cloud_get_info")) {
        opx_point_cloud_destroy(cloud);
        return false;
    }
    std::vector<float> xyz(3 * info.point_count);
    size_t count = 0;
    bool good = ok(opx_point_cloud_get_points(cloud, xyz.data(), info.point_count, 0, &count),
                   "opx_point_cloud_get_points");
    opx_point_cloud_destroy(cloud);
    uint32_t camera = 0;
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.robot = s.robot;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    good = good && ok(opx_linkset_find_link(s.robot, kCamera, &camera), "opx_linkset_find_link") &&
           ok(opx_linkset_get_pose(s.robot, camera, &insert.sensor_pose), "opx_linkset_get_pose") &&
           ok(opx_octree_create(&options, &s.map), "opx_octree_create") &&
           ok(opx_octree_insert_points(s.map, xyz.data(), count, 0, OPX_SCALAR_FLOAT32, &insert, &report),
              "opx_octree_insert_points") &&
           ok(opx_octree_get_stats(s.map, &stats), "opx_octree_get_stats");
    s.occupied_cells = stats.leaves_occupied;
    return good;
}

bool add_box(opx_world *world, const char *name, double sx, double sy, double sz, double x, double y, double z) {
    const opx_pose pose = {{x, y, z}, {0.0, 0.0, 0.0, 1.0}};
    opx_shape box = OPX_SHAPE_INIT;
    box.kind = OPX_SHAPE_BOX;
    box.size[0] = sx;
    box.size[1] = sy;
    box.size[2] = sz;
    uint32_t object = 0;
    return ok(opx_world_add_object(world, name, &pose, &object), "opx_world_add_object") &&
           ok(opx_world_add_shape(world, object, &box, nullptr), "opx_world_add_shape");
}

// Known objects besides the sensed map: a crate on the right and a post
// the arm has to pass.
bool load_world(Pr2Scene &s) {
    return ok(opx_world_create(&s.world), "opx_world_create") &&
           add_box(s.world, "crate", 0.3, 0.3, 0.3, 0.45, -0.75, 0.55) &&
           add_box(s.world, "post", 0.06, 0.06, 0.6, 0.55, -0.45, 0.9);
}

// The planner checks the right arm's links padded by kPlanningPadding: a
// collision thinner than a motion's step could otherwise slip between two
// of its configurations (the dense check then checks the robot unpadded).
// The body, which does not move, is left as it is.
bool pad_arm(opx_linkset *robot) {
    static const char *const kArmPrefixes[6] = {"r_shoulder", "r_upper_arm", "r_elbow", "r_forearm", "r_wrist", "r_gripper"};
    uint32_t links = 0;
    if (!ok(opx_linkset_get_link_count(robot, &links), "opx_linkset_get_link_count")) return false;
    for (uint32_t l = 0; l < links; ++l) {
        const char *name = "";
        if (!ok(opx_linkset_get_link_name(robot, l, &name), "opx_linkset_get_link_name")) return false;
        for (const char *prefix : kArmPrefixes)
            if (std::strncmp(name, prefix, std::strlen(prefix)) == 0 &&
                !ok(opx_linkset_set_link_padding(robot, l, kPlanningPadding), "opx_linkset_set_link_padding"))
                return false;
    }
    return true;
}

bool planned_joints(Pr2Scene &s) {
    uint32_t joints = 0;
    if (!ok(opx_linkset_get_joint_count(s.robot, &joints), "opx_linkset_get_joint_count")) return false;
    s.check.joint_positions.assign(joints, 0.0);
    size_t written = 0;
    if (!ok(opx_linkset_get_joint_positions(s.robot, s.check.joint_positions.data(), joints, &written),
            "opx_linkset_get_joint_positions"))
        return false;
    for (size_t j = 0; j < kArmJoints; ++j) {
        uint32_t index = 0;
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        if (!ok(opx_linkset_find_joint(s.robot, kArmJointNames[j], &index), "opx_linkset_find_joint") ||
            !ok(opx_linkset_get_joint_info(s.robot, index, &info), "opx_linkset_get_joint_info"))
            return false;
        s.check.planned_joints.push_back(index);
        const bool continuous = info.type == OPX_JOINT_CONTINUOUS;
        s.lower[j] = continuous ? -M_PI : info.lower;
        s.upper[j] = continuous ? M_PI : info.upper;
    }
    return true;
}

}  // namespace

Pr2Scene::~Pr2Scene() {
    opx_world_destroy(world);
    opx_octree_destroy(map);
    opx_linkset_destroy(robot);
}

int load_pr2_scene(const std::string &data_dir, double resolution, Pr2Scene &s) {
    for (const char *file : {kFrame, kUrdf, kSrdf})
        if (!exists(data_dir + "/" + file)) {
            // CI sets OPX_REQUIRE_DATA=1: there, missing data fails.
            const char *require = std::getenv("OPX_REQUIRE_DATA");
            const bool required = require != nullptr && std::strcmp(require, "1") == 0;
            std::fprintf(stderr, "%s: %s/%s not found: the shared data is absent (set OPX_DATA_DIR or --data)\n",
                         required ? "opx-ompl-plan" : "SKIP", data_dir.c_str(), file);
            return required ? 1 : kMissingData;
        }
    if (!load_robot(data_dir, s) || !load_map(data_dir, resolution, s) || !load_world(s) || !planned_joints(s))
        return 1;
    if (!pad_arm(s.robot)) return 1;
    s.check.map = s.map;
    s.check.world = s.world;
    s.check.robot = s.robot;
    return 0;
}

}  // namespace opx_ompl
