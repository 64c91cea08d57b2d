// Meshes are placed lazily: a pose update computes only a bounding box
// from a few of the mesh's tree nodes (or, asked for the cheap box, from
// its shape-frame box when it fits it), and the first query reaching the
// mesh places its vertices and refits its tree, once, from any number of
// threads.  Checked: the box holds every placed vertex, the exact box is
// bit for bit the placed vertices' box; a new pose unplaces the mesh, an
// unchanged pose keeps it placed; threads placing one mesh together all
// read the same vertices.
#include "robot/linkset.hpp"
#include "robot/mesh_bounds.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <thread>
#include <vector>

namespace {

using namespace octoprox;

Pose random_pose(std::mt19937_64 &rng) {
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    q.normalize();
    Pose pose;
    pose.rotation = q.toRotationMatrix();
    pose.translation = Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
    return pose;
}

// The box of the placed triangles' vertices.
Aabb placed_box(const ShapeDef &def, const Pose &pose) {
    Aabb box;
    for (const auto &t : def.triangles)
        for (uint32_t v : t) box.grow(Vec3(pose.rotation * def.vertices[v] + pose.translation));
    return box;
}

// The box of every placed vertex, used by a triangle or not (the exact box
// a cost box is cut from, as before meshes were placed lazily).
Aabb placed_vertex_box(const ShapeDef &def, const Pose &pose) {
    Aabb box;
    for (const Vec3 &v : def.vertices) box.grow(Vec3(pose.rotation * v + pose.translation));
    return box;
}

// One link holding one mesh, posed.
struct MeshLink {
    LinkSet links;
    explicit MeshLink(ShapeDef def) { links.add_shape(links.add_link("mesh"), std::move(def)); }
    explicit MeshLink(std::mt19937_64 &rng) : MeshLink(unit::random_mesh(rng, 400, 700)) {}
    const PlacedShape &shape() const { return links.placed()[0]; }
    bool placed() const { return shape().mesh_placement.done.load(); }
};

bool holds(const Aabb &outer, const Aabb &inner) {
    return (outer.lo.array() <= inner.lo.array()).all() && (inner.hi.array() <= outer.hi.array()).all();
}

TEST(MeshPlacement, BoxHoldsThePlacedMeshAndTheExactBoxIsItsBox) {
    std::mt19937_64 rng(7);
    for (int trial = 0; trial < 200; ++trial) {
        MeshLink mesh(unit::random_mesh(rng, 3 + trial * 5, 1 + trial * 7));
        const Pose pose = random_pose(rng);
        mesh.links.set_poses({pose});
        EXPECT_TRUE(holds(mesh.shape().box, placed_box(*mesh.shape().def, pose))) << "trial " << trial;
        const Aabb expected = placed_vertex_box(*mesh.shape().def, pose);
        EXPECT_FALSE(mesh.placed());
        const Aabb exact = mesh.shape().exact_box();
        EXPECT_TRUE(mesh.placed());
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_EQ(exact.lo[axis], expected.lo[axis]) << "trial " << trial << " axis " << axis;
            EXPECT_EQ(exact.hi[axis], expected.hi[axis]) << "trial " << trial << " axis " << axis;
        }
    }
}

// Points on a sphere (a golden-angle spiral) joined in a fan: a mesh that
// fills its shape-frame box poorly once rotated.
ShapeDef sphere_mesh(int points) {
    ShapeDef def;
    def.kind = ShapeKind::kMesh;
    for (int i = 0; i < points; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / points, r = std::sqrt(1.0 - z * z), a = 2.399963229728653 * i;
        def.vertices.emplace_back(r * std::cos(a), r * std::sin(a), z);
    }
    for (uint32_t i = 1; i + 1 < static_cast<uint32_t>(points); ++i) def.triangles.push_back({0, i, i + 1});
    build_mesh_tree(def);
    return def;
}

ShapeDef box_mesh(const Vec3 &half) {
    ShapeDef def;
    def.kind = ShapeKind::kMesh;
    for (int i = 0; i < 8; ++i)
        def.vertices.emplace_back(i & 1 ? half.x() : -half.x(), i & 2 ? half.y() : -half.y(),
                                  i & 4 ? half.z() : -half.z());
    def.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                     {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    build_mesh_tree(def);
    return def;
}

TEST(MeshPlacement, CheapBoxOnlyForMeshesThatFitTheirBox) {
    const ShapeDef box = box_mesh(Vec3(0.1, 0.2, 0.4));
    EXPECT_NEAR(rotated_box_looseness(box.mesh_tree.node(box.mesh_tree.root()).box, box.vertices), 1.0, 1e-9);
    EXPECT_FALSE(box.local_box.empty());
    const ShapeDef sphere = sphere_mesh(400);
    EXPECT_GT(rotated_box_looseness(sphere.mesh_tree.node(sphere.mesh_tree.root()).box, sphere.vertices),
              kCheapBoxLooseness);
    EXPECT_TRUE(sphere.local_box.empty());
}

// A batch's copy asks for cheap boxes: still bounds, and the exact box
// is unchanged.
TEST(MeshPlacement, CheapBoxHoldsThePlacedMesh) {
    std::mt19937_64 rng(11);
    int cheap = 0;
    for (int trial = 0; trial < 200; ++trial) {
        MeshLink mesh(trial % 4 == 0 ? box_mesh(Vec3(0.1, 0.3, 0.05) * (1 + trial % 7))
                                     : unit::random_mesh(rng, 3 + trial * 5, 1 + trial * 7));
        mesh.links.set_mesh_box(MeshBox::kCheap);
        const Pose pose = random_pose(rng);
        mesh.links.set_poses({pose});
        cheap += !mesh.shape().def->local_box.empty();
        EXPECT_TRUE(holds(mesh.shape().box, placed_box(*mesh.shape().def, pose))) << "trial " << trial;
        const Aabb expected = placed_vertex_box(*mesh.shape().def, pose);
        const Aabb exact = mesh.shape().exact_box();
        EXPECT_EQ(exact.lo, expected.lo) << "trial " << trial;
        EXPECT_EQ(exact.hi, expected.hi) << "trial " << trial;
    }
    EXPECT_GT(cheap, 100);
}

TEST(MeshPlacement, PosesUnplaceOnlyWhenTheyChange) {
    std::mt19937_64 rng(11);
    MeshLink mesh(rng);
    const Pose first = random_pose(rng), second = random_pose(rng);
    mesh.links.set_poses({first});
    mesh.links.set_poses({first});
    EXPECT_FALSE(mesh.placed()) << "a pose update must not place a mesh's vertices";
    mesh.shape().place_mesh();
    ASSERT_TRUE(mesh.placed());
    EXPECT_EQ(mesh.shape().mesh_tree.node(0).box.lo, placed_box(*mesh.shape().def, first).lo);
    mesh.links.set_poses({first});
    EXPECT_TRUE(mesh.placed()) << "an unchanged pose keeps the placement";
    mesh.links.set_poses({second});
    EXPECT_FALSE(mesh.placed()) << "a new pose must unplace the mesh";
    mesh.shape().place_mesh();
    EXPECT_EQ(mesh.shape().mesh_tree.node(0).box.hi, placed_box(*mesh.shape().def, second).hi);
    EXPECT_EQ(mesh.shape().exact_box().hi, placed_vertex_box(*mesh.shape().def, second).hi);
}

TEST(MeshPlacement, ThreadsPlacingTogetherReadTheSameVertices) {
    std::mt19937_64 rng(13);
    MeshLink mesh(rng);
    for (int round = 0; round < 20; ++round) {
        const Pose pose = random_pose(rng);
        mesh.links.set_poses({pose});
        const ShapeDef &def = *mesh.shape().def;
        std::vector<int> wrong(8, 0);
        std::vector<std::thread> threads;
        for (int t = 0; t < 8; ++t) {
            threads.emplace_back([&, t] {
                mesh.shape().place_mesh();
                for (size_t i = 0; i < def.triangles.size(); ++i) {
                    const Convex triangle = mesh.shape().triangle(static_cast<int32_t>(i));
                    for (int k = 0; k < 3; ++k)
                        wrong[t] += triangle.v[k] != Vec3(pose.rotation * def.vertices[def.triangles[i][k]] + pose.translation);
                }
            });
        }
        for (std::thread &thread : threads) thread.join();
        for (int t = 0; t < 8; ++t) EXPECT_EQ(wrong[t], 0) << "round " << round << " thread " << t;
    }
}

}  // namespace
