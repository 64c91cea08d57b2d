#include "bench_scene.hpp"

#include <cstdio>

#include "arm_urdf.hpp"
#include "bench_frame.hpp"
#include "pr2_scene.hpp"
#include "scene.hpp"

namespace batch_bench {
namespace {

using paper_tables::check_opx;

// The PR2 in the generated room, as opx-frame-bench places it: facing the
// table, its wheels 5.5 cm above the floor's cells.
const opx_pose kRoomBase = {{0.55, 0.0, 0.055}, {0.0, 0.0, 0.0, 1.0}};

size_t count_shapes(const opx_linkset *links) {
    uint32_t count = 0, total = 0;
    check_opx(opx_linkset_get_link_count(links, &count), "opx_linkset_get_link_count");
    for (uint32_t l = 0; l < count; ++l) {
        uint32_t shapes = 0;
        check_opx(opx_linkset_get_shape_count(links, l, &shapes), "opx_linkset_get_shape_count");
        total += shapes;
    }
    return total;
}

Robot finish(Robot robot) {
    uint32_t joints = 0;
    check_opx(opx_linkset_get_joint_count(robot.links.get(), &joints), "opx_linkset_get_joint_count");
    robot.joints = joints;
    robot.shapes = count_shapes(robot.links.get());
    return robot;
}

Robot load_arm(const std::string &name, const std::string &urdf, bool with_fcl) {
    opx_linkset *raw = nullptr;
    check_opx(opx_linkset_load_urdf_string(urdf.c_str(), nullptr, &raw), "opx_linkset_load_urdf_string");
    Robot robot;
    robot.name = name;
    robot.links.reset(raw);
    robot.disabled = adjacent_arm_links();
    for (const auto &pair : robot.disabled)
        check_opx(opx_linkset_set_pair_enabled(raw, pair.first, pair.second, 0), "opx_linkset_set_pair_enabled");
    if (with_fcl) robot.fcl = std::make_unique<paper_tables::FclRobot>(raw);
    return finish(std::move(robot));
}

LinkPairs disabled_pairs(const opx_linkset *links) {
    uint32_t count = 0;
    check_opx(opx_linkset_get_disabled_pair_count(links, &count), "opx_linkset_get_disabled_pair_count");
    LinkPairs pairs(count);
    for (uint32_t i = 0; i < count; ++i)
        check_opx(opx_linkset_get_disabled_pair(links, i, &pairs[i].first, &pairs[i].second),
                  "opx_linkset_get_disabled_pair");
    return pairs;
}

// The arms' base: the PR2's right shoulder with its root at `base` (the
// PR2 keeps its joint positions), moved kArmForward along the root's x, so
// the arms reach over the same surfaces as the PR2's reaching arms.
const double kArmForward = 0.25;

opx_pose shoulder_pose(opx_linkset *pr2, const opx_pose &base) {
    size_t count = 0;
    opx_linkset_get_joint_positions(pr2, nullptr, 0, &count);  // BUFFER_TOO_SMALL gives the count
    std::vector<double> q(count);
    check_opx(opx_linkset_get_joint_positions(pr2, q.data(), count, &count), "opx_linkset_get_joint_positions");
    check_opx(opx_linkset_set_joint_positions(pr2, q.data(), count, &base), "opx_linkset_set_joint_positions");
    uint32_t link = 0;
    check_opx(opx_linkset_find_link(pr2, "r_shoulder_pan_link", &link), "opx_linkset_find_link");
    opx_pose pose = OPX_POSE_IDENTITY;
    check_opx(opx_linkset_get_pose(pr2, link, &pose), "opx_linkset_get_pose");
    pose.position[0] += kArmForward;  // both scenes' roots face +x
    return pose;
}

void finish_scene(Scene &scene, opx_linkset *pr2) {
    scene.fcl_octree = paper_tables::wrap_octree(scene.octomap);
    scene.arm_base = shoulder_pose(pr2, scene.robot_base);
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(scene.tree.get(), &stats), "opx_octree_get_stats");
    scene.occupied = stats.leaves_occupied;
}

}  // namespace

Robot load_pr2() {
    const paper_tables::OpxLinksetPtr table_pr2 = paper_tables::load_pr2();  // the head tilt of Table IV
    const std::string root = paper_tables::data_root();
    const std::string urdf = root + "/robots/pr2_description/urdf/robot.xml";
    const std::string srdf = root + "/robots/pr2_description/srdf/pr2.srdf";
    const std::string package = "moveit_resources_pr2_description=" + root + "/robots/pr2_description";
    const char *dirs[1] = {package.c_str()};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs, options.package_dir_count = 1, options.srdf_path = srdf.c_str();
    opx_linkset *raw = nullptr;
    check_opx(opx_linkset_load_urdf_file(urdf.c_str(), &options, &raw), "opx_linkset_load_urdf_file");
    Robot robot;
    robot.name = "PR2";
    robot.links.reset(raw);
    size_t count = 0;
    opx_linkset_get_joint_positions(table_pr2.get(), nullptr, 0, &count);
    std::vector<double> q(count);
    check_opx(opx_linkset_get_joint_positions(table_pr2.get(), q.data(), count, &count), "opx_linkset_get_joint_positions");
    check_opx(opx_linkset_set_joint_positions(raw, q.data(), count, nullptr), "opx_linkset_set_joint_positions");
    robot.disabled = disabled_pairs(raw);
    robot.fcl = std::make_unique<paper_tables::FclRobot>(raw);
    return finish(std::move(robot));
}

Robot load_primitive_arm() { return load_arm("arm 7", primitive_arm_urdf(), true); }
Robot load_sphere_arm() { return load_arm("sphere arm 50", sphere_arm_urdf(), false); }

Scene real_scene(opx_linkset *pr2) {
    Scene scene;
    scene.name = "real frame 2 cm";
    paper_tables::FrameMaps maps = paper_tables::build_frame_maps(paper_tables::camera_pose(pr2), {kResolution}, 0);
    scene.tree = std::move(maps.opx);
    scene.octomap = paper_tables::mirror_through_bt(scene.tree.get(), kResolution);
    finish_scene(scene, pr2);
    return scene;
}

Scene room_scene(opx_linkset *pr2) {
    Scene scene;
    scene.name = "generated room 2 cm";
    const bench::Frame frame = bench::load_frame("", true);
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = kResolution;
    opx_octree *raw = nullptr;
    check_opx(opx_octree_create(&options, &raw), "opx_octree_create");
    scene.tree.reset(raw);
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_RAYCAST;
    insert.max_threads = 0;
    for (int i = 0; i < 3; ++i) insert.sensor_pose.position[i] = frame.position[i];
    for (int i = 0; i < 4; ++i) insert.sensor_pose.orientation[i] = frame.quaternion_xyzw[i];
    check_opx(opx_octree_insert_points(raw, frame.xyz.data(), frame.count, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
              "opx_octree_insert_points");
    scene.octomap = paper_tables::mirror_through_bt(raw, kResolution);
    scene.robot_base = kRoomBase;
    finish_scene(scene, pr2);
    return scene;
}

}  // namespace batch_bench
