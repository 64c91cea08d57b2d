// Exact distances between a robot shape and an axis-aligned box that need
// not be a cube: the part of an unknown cube inside a region of interest
// (the cost oracle clips unknown cubes to the region).  Same method as
// oracle_geometry.hpp for cubes: 0 when no separating axis exists (the box's
// 3 face normals, the piece's face normals, and every piece edge x box axis),
// else the minimum over feature pairs (each vertex of one vs the other solid,
// every edge vs every edge).  A box may be flat (zero extent on an axis): a
// rectangle, a segment or a point are still closed convex sets, and the
// same axes and features cover them.
//
// Cylinders are measured by FCL with both GJK solvers; when they disagree,
// exact inscribed and circumscribed prisms decide (as oracle_fcl.hpp).
#pragma once

#include "oracle_robot.hpp"

namespace oracle {

// A closed axis-aligned box, lo <= hi on every axis.
struct AlignedBox {
    Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();
    Vec3 center() const { return 0.5 * (lo + hi); }
    Vec3 half() const { return 0.5 * (hi - lo); }
    double volume() const { return (hi - lo).cwiseMax(0.0).prod(); }
};

AlignedBox aligned_box_of(const Cell &cell);
// The intersection of two boxes; `empty` when it is empty on some axis
// (touching boxes meet in a flat, non-empty box).
AlignedBox intersect(const AlignedBox &a, const AlignedBox &b, bool &empty);

double point_aligned_distance(const Vec3 &p, const AlignedBox &box);
double segment_aligned_distance(const Segment &s, const AlignedBox &box);
double triangle_aligned_distance(const Triangle &t, const AlignedBox &box);
double oriented_aligned_distance(const OrientedBox &b, const AlignedBox &box);
double polytope_aligned_distance(const Polytope &hull, const AlignedBox &box);
double cylinder_aligned_distance(const Cylinder &c, const AlignedBox &box);

// Distance between the shape's CORE (no inflation) and the box.
double shape_aligned_distance(const PlacedShape &shape, const AlignedBox &box);

}  // namespace oracle
