// A closed mesh's triangles as the self-filter's ray entry reads them: in
// the shape frame, each with its plane, and each edge and vertex assigned
// to exactly one of the triangles around it.  The solid a closed mesh
// bounds, grown by a ball, is the union of its triangles grown by that
// ball; a ray from outside first meets it on an offset face, on the
// cylinder around an edge or on the ball around a vertex.  An edge whose
// two faces meet clearly concave (a valley, seen from outside) never
// holds the point of the surface nearest a point outside the solid, so
// its cylinder lies inside the faces' grown slabs wherever it matters and
// is not tested.
#pragma once

#include "broadphase/aabb_tree.hpp"
#include "geometry/pose.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace octoprox {

struct MeshFace {
    Vec3 v[3];                 // shape frame
    Vec3 normal = Vec3::Zero();  // unit, either side; zero for a degenerate triangle
    double offset = 0.0;       // normal . v[0]
    double area2 = 0.0;        // |(v1 - v0) x (v2 - v0)|
    uint8_t edges = 0;         // bit k: this face tests the edge v[k] -> v[(k + 1) % 3]
    uint8_t vertices = 0;      // bit k: this face tests the ball around v[k]
};

using MeshFaces = std::vector<MeshFace>;

// The faces of a mesh whose edges are each shared by exactly two
// triangles (mesh_is_closed).  Concave edges are left untested only when
// the triangles are oriented consistently (every directed edge once).
std::shared_ptr<const MeshFaces> build_mesh_faces(const std::vector<Vec3> &vertices,
                                                  const std::vector<std::array<uint32_t, 3>> &triangles);

// A convex shape's hull as faces (all its edges convex), with a tree over
// them, both in the shape frame.
struct HullFaces {
    AabbTree tree;
    std::shared_ptr<const MeshFaces> faces;
};

// The hull of `vertices` (geometry/convex_hull.hpp) as faces; null when
// the vertices span no volume (such a hull is left to the exact convex
// distance).
std::shared_ptr<const HullFaces> build_hull_faces(const std::vector<Vec3> &vertices);

}  // namespace octoprox
