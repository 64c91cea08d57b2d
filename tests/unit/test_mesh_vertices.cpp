// keep_used_vertices: unused vertices dropped, indices renumbered in first
// use order, and with kSamePosition equal positions (-0 as +0) welded.
#include "robot/mesh_vertices.hpp"

#include <gtest/gtest.h>

using octoprox::keep_used_vertices;
using octoprox::Vec3;
using octoprox::VertexWeld;
using Triangles = std::vector<std::array<uint32_t, 3>>;

namespace {

// Vertex 0 is unused; 2 and 4 sit at one position (4 with a -0).
std::vector<Vec3> vertices_with_a_copy() {
    return {Vec3(9, 9, 9), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1), Vec3(-0.0, 1, 0)};
}

}  // namespace

TEST(MeshVertices, UnusedVerticesGoAndIndicesFollowFirstUse) {
    std::vector<Vec3> vertices = vertices_with_a_copy();
    Triangles triangles = {{3, 1, 2}, {1, 4, 3}};
    keep_used_vertices(vertices, triangles, VertexWeld::kNone);
    const std::vector<Vec3> expected = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-0.0, 1, 0)};
    EXPECT_EQ(vertices, expected);
    EXPECT_EQ(triangles, (Triangles{{0, 1, 2}, {1, 3, 0}}));
}

TEST(MeshVertices, SamePositionsWeld) {
    std::vector<Vec3> vertices = vertices_with_a_copy();
    Triangles triangles = {{3, 1, 2}, {1, 4, 3}};
    keep_used_vertices(vertices, triangles, VertexWeld::kSamePosition);
    const std::vector<Vec3> expected = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    EXPECT_EQ(vertices, expected);
    EXPECT_EQ(triangles, (Triangles{{0, 1, 2}, {1, 2, 0}}));
}

TEST(MeshVertices, AMeshUsingEveryVertexInOrderIsUnchanged) {
    const std::vector<Vec3> original = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    std::vector<Vec3> vertices = original;
    Triangles triangles = {{0, 1, 2}};
    for (VertexWeld weld : {VertexWeld::kNone, VertexWeld::kSamePosition}) {
        keep_used_vertices(vertices, triangles, weld);
        EXPECT_EQ(vertices, original);
        EXPECT_EQ(triangles, (Triangles{{0, 1, 2}}));
    }
}
