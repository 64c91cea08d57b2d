// real_pr2_urdf: the PR2 of the shared data as a link set.  Links, joints,
// collision elements and meshes are counted by the test's own scan of the
// URDF text; FK at zero and at random joint values matches poses composed
// by hand (urdf_scanner.cpp) for every link; the full SRDF's pairs load.
#include "real_support.hpp"
#include "urdf_scanner.hpp"

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

namespace {

std::string g_urdf_path, g_srdf_path, g_package_entry;
scan::Robot g_scan;

std::string read_text(const std::string &path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

opx_linkset *load_pr2(const char *srdf = nullptr) {
    const char *dirs[1] = {g_package_entry.c_str()};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    options.srdf_path = srdf;
    opx_linkset *robot = nullptr;
    real::check_ok(opx_linkset_load_urdf_file(g_urdf_path.c_str(), &options, &robot), "opx_linkset_load_urdf_file");
    return robot;
}

// Triangles of the collision STLs (data README).
const std::map<std::string, uint32_t> kTriangles = {
    {"base_L.stl", 96}, {"caster_L.stl", 188}, {"torso_lift_L.stl", 150}, {"head_pan_L.stl", 220},
    {"head_tilt_L.stl", 106}, {"tilting_hokuyo_L.stl", 90}, {"shoulder_pan.stl", 1000},
    {"shoulder_lift.stl", 965}, {"upper_arm_roll_L.stl", 100}, {"upper_arm.stl", 1600},
    {"elbow_flex.stl", 1000}, {"forearm_roll_L.stl", 200}, {"forearm.stl", 1700}, {"wrist_flex.stl", 986},
    {"wrist_roll_L.stl", 150}, {"gripper_palm.stl", 1000}, {"l_finger.stl", 1863}, {"l_finger_tip.stl", 998}};

int32_t kind_code(const std::string &kind) {
    if (kind == "box") return OPX_SHAPE_BOX;
    if (kind == "sphere") return OPX_SHAPE_SPHERE;
    if (kind == "cylinder") return OPX_SHAPE_CYLINDER;
    return OPX_SHAPE_MESH;
}

void test_scan_agrees_with_the_data_readme(void **) {
    size_t collisions = 0, meshes = 0;
    for (const scan::Link &l : g_scan.links) {
        collisions += l.collisions.size();
        for (const scan::Collision &c : l.collisions) meshes += c.kind == "mesh";
    }
    assert_int_equal(g_scan.links.size(), 95);
    assert_int_equal(g_scan.joints.size(), 94);
    assert_int_equal(collisions, 54);
    assert_int_equal(meshes, 37);
}

// Every link in file order with every collision element, in order and of
// its kind; every mesh with the triangles of its file.
void test_every_link_and_collision_is_loaded(void **) {
    opx_linkset *robot = load_pr2();
    uint32_t links = 0;
    real::check_ok(opx_linkset_get_link_count(robot, &links), "opx_linkset_get_link_count");
    assert_int_equal(links, g_scan.links.size());
    size_t meshes = 0;
    for (uint32_t i = 0; i < links; ++i) {
        const scan::Link &expected = g_scan.links[i];
        const char *name = nullptr;
        uint32_t shapes = 0;
        real::check_ok(opx_linkset_get_link_name(robot, i, &name), "opx_linkset_get_link_name");
        assert_string_equal(name, expected.name.c_str());
        real::check_ok(opx_linkset_get_shape_count(robot, i, &shapes), "opx_linkset_get_shape_count");
        assert_int_equal(shapes, expected.collisions.size());
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            real::check_ok(opx_linkset_get_shape(robot, i, s, &shape), "opx_linkset_get_shape");
            const scan::Collision &c = expected.collisions[s];
            assert_int_equal(shape.kind, kind_code(c.kind));
            if (shape.kind != OPX_SHAPE_MESH) continue;
            ++meshes;
            const std::string file = c.filename.substr(c.filename.rfind('/') + 1);
            if (shape.triangle_count != kTriangles.at(file))
                fail_msg("link %s mesh %s: %zu triangles, expected %u", name, file.c_str(), shape.triangle_count,
                         kTriangles.at(file));
        }
    }
    assert_int_equal(meshes, 37);
    opx_linkset_destroy(robot);
}

void test_joints_follow_the_file(void **) {
    opx_linkset *robot = load_pr2();
    uint32_t count = 0;
    real::check_ok(opx_linkset_get_joint_count(robot, &count), "opx_linkset_get_joint_count");
    assert_int_equal(count, g_scan.joints.size());
    const std::map<std::string, int32_t> types = {{"fixed", OPX_JOINT_FIXED}, {"revolute", OPX_JOINT_REVOLUTE},
                                                  {"continuous", OPX_JOINT_CONTINUOUS},
                                                  {"prismatic", OPX_JOINT_PRISMATIC}};
    for (uint32_t j = 0; j < count; ++j) {
        const scan::Joint &expected = g_scan.joints[j];
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        real::check_ok(opx_linkset_get_joint_info(robot, j, &info), "opx_linkset_get_joint_info");
        assert_string_equal(info.name, expected.name.c_str());
        assert_int_equal(info.type, types.at(expected.type));
        const char *parent = nullptr, *child = nullptr;
        real::check_ok(opx_linkset_get_link_name(robot, info.parent_link, &parent), "parent name");
        real::check_ok(opx_linkset_get_link_name(robot, info.child_link, &child), "child name");
        assert_string_equal(parent, expected.parent.c_str());
        assert_string_equal(child, expected.child.c_str());
        if (expected.has_limit && expected.type != "continuous") {
            assert_true(info.has_limits == 1 && info.lower == expected.lower && info.upper == expected.upper);
        }
        if (expected.mimic.empty()) {
            assert_int_equal(info.mimic_joint, OPX_JOINT_NONE);
        } else {
            uint32_t master = 0;
            real::check_ok(opx_linkset_find_joint(robot, expected.mimic.c_str(), &master), "find master");
            assert_int_equal(info.mimic_joint, master);
        }
    }
    opx_linkset_destroy(robot);
}

// Every link's pose equals the hand-composed frame within 1e-9.
void assert_matches(const opx_linkset *robot, const std::map<std::string, scan::Frame> &expected) {
    for (uint32_t i = 0; i < g_scan.links.size(); ++i) {
        opx_pose pose;
        real::check_ok(opx_linkset_get_pose(robot, i, &pose), "opx_linkset_get_pose");
        const scan::Frame &f = expected.at(g_scan.links[i].name);
        const Eigen::Vector3d position(pose.position[0], pose.position[1], pose.position[2]);
        const double dp = (position - f.pos).cwiseAbs().maxCoeff();
        const double dr = (scan::quaternion_matrix(pose.orientation) - f.rot).cwiseAbs().maxCoeff();
        if (!(dp <= 1e-9 && dr <= 1e-9))
            fail_msg("link %s: position off by %.3g, rotation by %.3g", g_scan.links[i].name.c_str(), dp, dr);
    }
}

// Random values for every joint: within the limits where they exist;
// fixed and mimic joints get garbage the library must ignore.
std::vector<double> random_positions(std::mt19937 &rng, std::map<std::string, double> &by_name) {
    std::vector<double> values;
    for (const scan::Joint &j : g_scan.joints) {
        double lo = -M_PI, hi = M_PI;
        if (j.has_limit && j.type != "continuous") lo = j.lower, hi = j.upper;
        const double v = std::uniform_real_distribution<double>(lo, hi)(rng);
        const bool ignored = j.type == "fixed" || !j.mimic.empty();
        values.push_back(ignored ? 1000.0 + v : v);
        by_name[j.name] = v;
    }
    return values;
}

void test_fk_matches_hand_composed_frames(void **) {
    opx_linkset *robot = load_pr2();
    std::map<std::string, double> zeros;
    for (const scan::Joint &j : g_scan.joints) zeros[j.name] = 0.0;
    assert_matches(robot, scan::forward_kinematics(g_scan, zeros, scan::Frame()));

    std::mt19937 rng(20261122);
    for (int trial = 0; trial < 25; ++trial) {
        std::map<std::string, double> by_name;
        const std::vector<double> values = random_positions(rng, by_name);
        scan::Frame root;
        root.pos = Eigen::Vector3d(trial * 0.5 - 3.0, 1.5, 0.2 * trial);
        const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.2, 1.0).normalized();
        root.rot = scan::axis_angle_matrix(axis, 0.3 * trial);
        const double half = 0.15 * trial;  // the same rotation as a quaternion
        const opx_pose base = {{root.pos.x(), root.pos.y(), root.pos.z()},
                               {axis.x() * std::sin(half), axis.y() * std::sin(half), axis.z() * std::sin(half),
                                std::cos(half)}};
        real::check_ok(opx_linkset_set_joint_positions(robot, values.data(), values.size(), &base),
                       "opx_linkset_set_joint_positions");
        assert_matches(robot, scan::forward_kinematics(g_scan, by_name, root));
    }
    opx_linkset_destroy(robot);
}

// The chains of the task by name: torso lift (prismatic), head tilt, the
// right arm to the palm; the other joints stay at 0.
void test_named_chains(void **) {
    opx_linkset *robot = load_pr2();
    const std::vector<std::pair<const char *, double>> set = {
        {"torso_lift_joint", 0.21}, {"head_pan_joint", -0.4}, {"head_tilt_joint", 0.6},
        {"r_shoulder_pan_joint", -0.7}, {"r_shoulder_lift_joint", 0.3}, {"r_upper_arm_roll_joint", -1.1},
        {"r_elbow_flex_joint", -1.2}, {"r_forearm_roll_joint", 2.0}, {"r_wrist_flex_joint", -0.9},
        {"r_wrist_roll_joint", 0.4}, {"r_gripper_l_finger_joint", 0.3}};
    std::vector<const char *> names;
    std::vector<double> values;
    std::map<std::string, double> by_name;
    for (const scan::Joint &j : g_scan.joints) by_name[j.name] = 0.0;
    for (const auto &[name, value] : set) names.push_back(name), values.push_back(value), by_name[name] = value;
    real::check_ok(opx_linkset_set_named_joint_positions(robot, names.data(), values.data(), names.size(), nullptr),
                   "opx_linkset_set_named_joint_positions");
    const std::map<std::string, scan::Frame> expected = scan::forward_kinematics(g_scan, by_name, scan::Frame());
    assert_matches(robot, expected);
    // The torso rises by exactly its prismatic value.
    opx_pose torso;
    uint32_t link = 0;
    real::check_ok(opx_linkset_find_link(robot, "torso_lift_link", &link), "find torso");
    real::check_ok(opx_linkset_get_pose(robot, link, &torso), "torso pose");
    std::map<std::string, double> zero = by_name;
    zero["torso_lift_joint"] = 0.0;
    assert_true(std::fabs(torso.position[2] - 0.21 -
                          scan::forward_kinematics(g_scan, zero, scan::Frame()).at("torso_lift_link").pos.z()) < 1e-12);
    opx_linkset_destroy(robot);
}

void test_srdf_pairs(void **) {
    const size_t expected = scan::elements(scan::without_comments(read_text(g_srdf_path)), "disable_collisions").size();
    assert_int_equal(expected, 1081);
    opx_linkset *robot = load_pr2(g_srdf_path.c_str());
    uint32_t count = 0;
    real::check_ok(opx_linkset_get_disabled_pair_count(robot, &count), "opx_linkset_get_disabled_pair_count");
    assert_int_equal(count, expected);
    opx_linkset_destroy(robot);
}

}  // namespace

int main() {
    g_urdf_path = real::require_data_file("robots/pr2_description/urdf/robot.xml");
    g_srdf_path = real::require_data_file("robots/pr2_description/srdf/pr2.srdf");
    // The URDF names its meshes package://moveit_resources_pr2_description/...
    // and the data keeps that package in pr2_description/ (data README).
    g_package_entry = "moveit_resources_pr2_description=" + real::data_dir() + "/robots/pr2_description";
    g_scan = scan::read_robot(read_text(g_urdf_path));
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scan_agrees_with_the_data_readme),
        cmocka_unit_test(test_every_link_and_collision_is_loaded),
        cmocka_unit_test(test_joints_follow_the_file),
        cmocka_unit_test(test_fk_matches_hand_composed_frames),
        cmocka_unit_test(test_named_chains),
        cmocka_unit_test(test_srdf_pairs),
    };
    return cmocka_run_group_tests_name("real_pr2_urdf", tests, nullptr, nullptr);
}
