// Forward kinematics inside the library: once a URDF link set is built and
// posed, new joint positions allocate nothing (joint tree, link placement,
// mesh and link BVH refits), and FK answers a simple chain exactly.  FK cut
// to the joints toward some links poses those links as the whole FK does.
#include "alloc_counter.hpp"

#include "robot/joint_tree.hpp"
#include "robot/urdf_model.hpp"

#include <gtest/gtest.h>

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

// base -> a (shapeless) -> b, base -> c (shapeless leaf), a -> d (leaf):
// toward b, FK keeps the joints to a and b alone, and poses them bit for
// bit as the whole FK does, leaving c and d as they were.
TEST(Kinematics, OrderTowardNeededLinks) {
    auto joint = [](const char *name, uint32_t parent, uint32_t child, JointType type) {
        Joint j;
        j.name = name, j.type = type, j.parent_link = parent, j.child_link = child;
        j.origin.translation = Vec3(0.1 * child, 0.2, 0.05 * parent);
        j.origin.rotation = Eigen::AngleAxisd(0.3 * child, Vec3(1, 2, 3).normalized()).toRotationMatrix();
        j.axis = Vec3(0, 0, 1);
        return j;
    };
    JointTree tree;
    tree.build({joint("to_a", 0, 1, JointType::kRevolute), joint("to_b", 1, 2, JointType::kContinuous),
                joint("to_c", 0, 3, JointType::kRevolute), joint("to_d", 1, 4, JointType::kFixed)},
               5, 0, "test");
    const std::vector<uint32_t> order = tree.order_toward({0, 0, 1, 0, 0});
    ASSERT_EQ(order.size(), 2u);
    EXPECT_EQ(tree.joint(order[0]).name, "to_a");
    EXPECT_EQ(tree.joint(order[1]).name, "to_b");

    const double first[4] = {0.1, 0.2, 0.3, 0.0}, next[4] = {-0.7, 1.1, 2.0, 0.0};
    std::vector<Pose> whole(5), cut(5);
    tree.link_poses(Pose(), first, whole.data());
    tree.link_poses(Pose(), first, cut.data());
    const std::vector<Pose> before = cut;
    uint8_t moved[5] = {};
    tree.link_poses(Pose(), next, whole.data());
    tree.update_link_poses(Pose(), false, next, first, cut.data(), moved, order);
    for (uint32_t link : {1u, 2u}) {
        EXPECT_TRUE(cut[link].rotation == whole[link].rotation && cut[link].translation == whole[link].translation);
        EXPECT_EQ(moved[link], 1) << link;
    }
    for (uint32_t link : {3u, 4u}) {
        EXPECT_TRUE(cut[link].rotation == before[link].rotation && cut[link].translation == before[link].translation);
        EXPECT_EQ(moved[link], 0) << link;
    }
}


}  // namespace
