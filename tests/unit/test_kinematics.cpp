// Forward kinematics inside the library: once a URDF link set is built and
// posed, new joint positions allocate nothing (joint tree, link placement,
// mesh and link BVH refits), and FK answers a simple chain exactly.  With
// the shared data, the PR2's FK rate is printed (reported, not asserted).
#include "alloc_counter.hpp"

#include "robot/urdf_model.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace {

using namespace octoprox;

const char kArm[] =
    "<robot name=\"arm\"><link name=\"base\"><collision><geometry><box size=\"0.2 0.2 0.2\"/></geometry></collision></link>"
    "<link name=\"upper\"><collision><origin xyz=\"0.25 0 0\"/><geometry><cylinder radius=\"0.05\" length=\"0.5\"/>"
    "</geometry></collision></link>"
    "<link name=\"lower\"><collision><geometry><sphere radius=\"0.04\"/></geometry></collision></link>"
    "<joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"upper\"/>"
    "<origin xyz=\"0 0 0.1\"/><axis xyz=\"0 0 1\"/><limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>"
    "<joint name=\"slide\" type=\"prismatic\"><parent link=\"upper\"/><child link=\"lower\"/>"
    "<origin xyz=\"0.5 0 0\"/><axis xyz=\"1 0 0\"/><limit lower=\"0\" upper=\"1\" effort=\"1\" velocity=\"1\"/></joint>"
    "</robot>";

// A tetrahedron mesh, so mesh placement and its tree refit are exercised.
ShapeDef tetra_mesh() {
    ShapeDef def;
    def.kind = ShapeKind::kMesh;
    def.vertices = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 0, 0.1)};
    def.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return def;
}

TEST(Kinematics, NewPositionsAllocateNothing) {
    LinkSet links;
    RobotModel robot;
    UrdfInput input;
    input.xml = kArm;
    input.source = "xml";
    load_urdf(input, links, robot);
    links.add_shape(2, tetra_mesh());
    robot.apply(links, Pose());  // the first poses after a shape change rebuild the tree

    const uint64_t before = unit::allocation_count();
    for (int i = 0; i < 1000; ++i) {
        const double q[2] = {std::sin(0.01 * i), 0.5 + 0.4 * std::cos(0.02 * i)};
        robot.joints.set_commanded(q);
        robot.joints.update_positions();
        robot.apply(links, Pose());
    }
    EXPECT_EQ(unit::allocation_count(), before);

    // The last configuration, by hand: lower = (0,0,0.1) + Rz(a) (0.5 + s, 0, 0).
    const double a = std::sin(0.01 * 999), s = 0.5 + 0.4 * std::cos(0.02 * 999);
    const Vec3 lower = links.link(2).pose.translation;
    EXPECT_NEAR(lower.x(), (0.5 + s) * std::cos(a), 1e-12);
    EXPECT_NEAR(lower.y(), (0.5 + s) * std::sin(a), 1e-12);
    EXPECT_NEAR(lower.z(), 0.1, 1e-12);
}

// Reported, not asserted: the rate of FK plus link placement on the PR2.
TEST(Kinematics, Pr2Rate) {
    const char *env = std::getenv("OPX_DATA_DIR");
    const std::string dir = std::string(env != nullptr ? env : OPX_DEFAULT_DATA_DIR) + "/robots/pr2_description";
    if (!file_exists(dir + "/urdf/robot.xml")) GTEST_SKIP() << "no PR2 in " << dir;
    UrdfInput input;
    std::FILE *f = std::fopen((dir + "/urdf/robot.xml").c_str(), "rb");
    ASSERT_NE(f, nullptr);
    for (int c; (c = std::fgetc(f)) != EOF;) input.xml.push_back(static_cast<char>(c));
    std::fclose(f);
    input.source = "pr2";
    input.paths.package_dirs = {"moveit_resources_pr2_description=" + dir};
    LinkSet links;
    RobotModel robot;
    load_urdf(input, links, robot);
    std::vector<double> q(robot.joints.joint_count(), 0.0);
    std::vector<Pose> poses(links.link_count());
    const int n = 2000;
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) {
        q[i % q.size()] = 0.001 * i;
        robot.joints.set_commanded(q.data());
        robot.joints.update_positions();
        robot.joints.link_poses(Pose(), poses);
    }
    const double fk_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() / n;
    start = std::chrono::steady_clock::now();
    for (int i = 0; i < n; ++i) {
        q[i % q.size()] = 0.001 * i;
        robot.joints.set_commanded(q.data());
        robot.joints.update_positions();
        robot.apply(links, Pose());
    }
    const double all_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count() / n;
    std::printf("PR2 (%zu joints, %zu links): FK alone %.2f us, FK + placing all shapes %.1f us per configuration\n",
                robot.joints.joint_count(), links.link_count(), fk_us, all_us);
}

}  // namespace
