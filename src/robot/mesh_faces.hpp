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

#include "geometry/aabb.hpp"
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
    Vec3 centre = Vec3::Zero();  // of the vertices' box
    double reach = 0.0;          // from centre to the farthest vertex
    uint8_t edges = 0;         // bit k: this face tests the edge v[k] -> v[(k + 1) % 3]
    uint8_t vertices = 0;      // bit k: this face tests the ball around v[k]
};

// A node of the faces' tree: a leaf holds up to kFacesPerLeaf faces, in
// a run of MeshFaces::faces.  A ray near a mesh crosses the boxes of many
// small faces once they are grown by a padding of their own size, so a
// leaf of a few faces costs the walk little selectivity and saves it most
// of its nodes.
struct FaceNode {
    Aabb box;
    int32_t left = -1, right = -1;  // children; -1 for a leaf
    uint32_t first = 0, count = 0;  // a leaf's faces
    bool is_leaf() const { return left < 0; }
};

constexpr uint32_t kFacesPerLeaf = 4;

struct MeshFaces {
    std::vector<MeshFace> faces;  // in the tree's leaf order
    std::vector<FaceNode> nodes;  // root first
};

// The faces of a mesh whose edges are each shared by exactly two
// triangles (mesh_is_closed).  Concave edges are left untested only when
// the triangles are oriented consistently (every directed edge once).
std::shared_ptr<const MeshFaces> build_mesh_faces(const std::vector<Vec3> &vertices,
                                                  const std::vector<std::array<uint32_t, 3>> &triangles);

// The hull of `vertices` (geometry/convex_hull.hpp) as the faces of a
// closed mesh (all its edges convex); null when the vertices span no
// volume (such a hull is left to the exact convex distance).
std::shared_ptr<const MeshFaces> build_hull_faces(const std::vector<Vec3> &vertices);

}  // namespace octoprox
