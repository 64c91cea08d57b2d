// Robot shapes: their definition in the shape frame (ShapeDef) and their
// placement in the map frame at the current link pose (PlacedShape).
//
// Every shape is a convex core plus a ball (the Minkowski sum is exact):
// a sphere is a point plus its radius, a capsule a segment plus its radius,
// and padding adds to that ball.  A mesh is many triangle cores sharing one
// ball, under a BVH over its triangles.
#pragma once

#include "broadphase/aabb_tree.hpp"
#include "geometry/convex.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace octoprox {

enum class ShapeKind : int { kSphere = 1, kBox, kCylinder, kCapsule, kConvex, kMesh };

struct ShapeDef {
    ShapeKind kind = ShapeKind::kSphere;
    Pose local;               // shape frame in the link frame
    double radius = 0.0;      // sphere, cylinder, capsule
    double half_length = 0.0; // cylinder, capsule (half of the axis part)
    Vec3 half_size = Vec3::Zero();  // box
    std::vector<Vec3> vertices;     // convex, mesh (shape frame)
    std::vector<std::array<uint32_t, 3>> triangles;  // mesh
    AabbTree mesh_tree;             // mesh: topology over the triangles, built once
};

// Builds a mesh's triangle tree (in the shape frame); call once per mesh.
void build_mesh_tree(ShapeDef &def);

struct PlacedShape {
    uint32_t link = 0, shape = 0;
    ShapeKind kind = ShapeKind::kSphere;
    double inflation = 0.0;  // radius of the ball added to the core
    Convex core;             // every kind but mesh
    Aabb box;                // bounds of the inflated shape; empty when disabled
    std::vector<Vec3> world_vertices;  // convex hull and mesh, map frame
    AabbTree mesh_tree;                // mesh: refit in the map frame
    std::vector<Aabb> triangle_box_scratch;  // mesh: reused by every placement
    const ShapeDef *def = nullptr;

    // A triangle of the mesh as a convex core.
    Convex triangle(int32_t index) const;
};

// Places `def` at link pose `link_pose` with `padding`; enabled=false
// leaves an empty box so the shape takes part in nothing.
void place_shape(const ShapeDef &def, const Pose &link_pose, double padding, bool enabled,
                 PlacedShape &out);

}  // namespace octoprox
