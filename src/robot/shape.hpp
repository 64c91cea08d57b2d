// Robot shapes: their definition in the shape frame (ShapeDef) and their
// placement in the map frame at the current link pose (PlacedShape).
//
// Every shape is a convex core plus a ball (the Minkowski sum is exact):
// a sphere is a point plus its radius, a capsule a segment plus its radius,
// and padding adds to that ball.  A mesh is many triangle cores sharing one
// ball, under a BVH over its triangles.
#pragma once

#include "base/lazy_value.hpp"
#include "broadphase/aabb_tree.hpp"
#include "geometry/convex.hpp"
#include "robot/box_columns.hpp"
#include "robot/mesh_faces.hpp"

#include <array>
#include <atomic>
#include <mutex>
#include <utility>
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
    // Mesh: what its box after a pose update is the union of (shape
    // frame): its vertices when they are few (the exact box), else the
    // boxes of the triangle tree's nodes a few levels down (at most 16),
    // whose union bounds the mesh a little loosely for the price of a few
    // dozen flops each, where the exact box needs every vertex.
    BoxColumns bounds;
    // Mesh: its shape-frame box (the triangle tree's root box) when the
    // mesh fits it well (kCheapBoxLooseness); else empty.
    Aabb local_box;
    // Mesh: every edge shared by exactly two triangles (mesh_closure.hpp).
    bool closed = false;
    // Convex and open mesh: a subset of the vertices holding every vertex
    // of their hull (shape frame), made by the first self-filtered insert
    // that needs it (self_filter/hull_vertices.hpp).
    LazyValue<std::vector<Vec3>> hull_vertices;
    // Closed mesh: its faces as the self-filter's ray entry reads them
    // (mesh_faces.hpp), made by the first self-filtered insert that needs
    // them.
    LazyValue<std::shared_ptr<const MeshFaces>> faces;
    // Convex and open mesh: the hull of hull_vertices as faces, made the
    // same way; null when it spans no volume.
    LazyValue<std::shared_ptr<const MeshFaces>> hull_faces;
};

// Builds a mesh's triangle tree (in the shape frame); call once per mesh.
void build_mesh_tree(ShapeDef &def);

// A mesh's placement in the map frame is done by the first query that
// reaches the mesh, once per pose, under a lock: queries on one link set
// may run in many threads, and most meshes of a robot are never reached by
// a query (their box touches no obstacle).  A copy starts unplaced.
struct LazyPlacement {
    std::atomic<bool> done{false};
    std::mutex lock;
    LazyPlacement() = default;
    LazyPlacement(const LazyPlacement &) noexcept {}
    LazyPlacement &operator=(const LazyPlacement &) noexcept {
        done.store(false);
        return *this;
    }
};

// The fields the distance search's lower bounds read (kind, inflation,
// core) come first: it prefetches a shape's first 160 bytes
// (direct_distance.cpp); keep them there.
struct PlacedShapeFields {
    uint32_t link = 0, shape = 0;
    ShapeKind kind = ShapeKind::kSphere;
    double inflation = 0.0;  // radius of the ball added to the core
    Convex core;             // every kind but mesh (a mesh's core holds only its pose: center, axes)
    // Bounds of the inflated shape, empty when disabled: exact for every
    // kind but a mesh of many vertices, whose box is the union of its
    // placed frontier boxes, or a mesh placed with MeshBox::kCheap, whose
    // box may be its placed shape-frame box (bounds for culling;
    // exact_box() gives the tight one).
    Aabb box;
    // Convex hull: map frame.  Mesh: map frame once place_mesh() ran.
    mutable std::vector<Vec3> world_vertices;
    mutable AabbTree mesh_tree;                        // mesh: refit in the map frame by place_mesh()
    mutable std::vector<Aabb> triangle_box_scratch;    // mesh: reused by every placement
    mutable LazyPlacement mesh_placement;
    mutable Aabb mesh_vertex_box;                      // mesh: of the placed vertices, by place_mesh()
    const ShapeDef *def = nullptr;
    // A shape of an object attached to the link (LinkSet::attach): the
    // object's index, `shape` being the shape's index within the object;
    // -1: one of the link's own shapes.
    int32_t attached = -1;
};

// A convex hull's core points into the shape's own world_vertices, so a
// copy or a move (a vector of shapes growing) points its core at its own
// vertices, never at the ones it was made from.
struct PlacedShape : PlacedShapeFields {
    PlacedShape() = default;
    PlacedShape(const PlacedShape &other) : PlacedShapeFields(other) { own_hull(); }
    PlacedShape(PlacedShape &&other) noexcept : PlacedShapeFields(std::move(other)) { own_hull(); }
    PlacedShape &operator=(const PlacedShape &other) {
        PlacedShapeFields::operator=(other);
        own_hull();
        return *this;
    }
    PlacedShape &operator=(PlacedShape &&other) noexcept {
        PlacedShapeFields::operator=(std::move(other));
        own_hull();
        return *this;
    }

    // Mesh: places the vertices and refits the triangle tree at the current
    // pose unless done already.  Call it before reading world_vertices,
    // mesh_tree or triangle() of a mesh; thread-safe.
    void place_mesh() const;
    // The tightest box of the inflated shape (a mesh: of all its placed
    // vertices, placing it); empty when disabled.  Cost boxes use it.
    Aabb exact_box() const;
    // A triangle of the (placed) mesh as a convex core.
    Convex triangle(int32_t index) const;
    // The same triangle placed from the shape-frame vertices, bit for bit
    // as place_mesh() places them; needs no placement.
    Convex posed_triangle(int32_t index) const;

private:
    void own_hull() {
        if (kind == ShapeKind::kConvex) core.hull = world_vertices.data();
    }
};

// Which box a mesh gets when placed: the tight one (its vertices' box or
// its frontier boxes' union), or, where each pose is checked once (a
// batch's own copy of a robot), its placed shape-frame box when it has
// one: cheaper to place, looser to cull with; the answers are the same.
enum class MeshBox { kTight, kCheap };

// Places `def` at link pose `link_pose` with `padding`; enabled=false
// leaves an empty box so the shape takes part in nothing.
void place_shape(const ShapeDef &def, const Pose &link_pose, double padding, bool enabled, PlacedShape &out,
                 MeshBox mesh_box = MeshBox::kTight);

}  // namespace octoprox
