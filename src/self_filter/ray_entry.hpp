// Where a ray first comes within a radius of a point, a segment or a
// triangle, in closed form: the grown core's surface is made of sphere,
// cylinder and plane pieces, and the entry is the first of their hits.
// The robot's sphere, capsule and mesh solids take these instead of
// Newton's iteration (solid_geometry.hpp), whose every step needs a
// nearest point.
#pragma once

#include "geometry/convex.hpp"
#include "robot/mesh_faces.hpp"

namespace octoprox {

// The first t in [0, t_max] at which origin + t * dir lies within `radius`
// of the core (a point, a segment or a triangle), or -1.  The origin lies
// farther than `radius` from the core.
double closed_form_entry(const Convex &core, double radius, const Vec3 &origin, const Vec3 &dir, double t_max);

// The first t in [0, t_max] at which origin + t * dir lies within `radius`
// of what `face` tests of its closed mesh (its triangle's plane piece, the
// edges and vertices assigned to it), or -1: over a mesh's faces, the
// first of these is where the ray enters the mesh's solid grown by
// `radius` (mesh_faces.hpp).  The origin lies outside that grown solid.
double face_entry(const MeshFace &face, double radius, const Vec3 &origin, const Vec3 &dir, double t_max);

// Whether closed_form_entry takes this core.
inline bool has_closed_form_entry(const Convex &core) {
    return core.kind == ConvexKind::kPoint || core.kind == ConvexKind::kSegment || core.kind == ConvexKind::kTriangle;
}

}  // namespace octoprox
