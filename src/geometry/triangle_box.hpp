// A triangle against an axis-aligned box by separating axes: the box's 3
// face normals, the triangle's normal and the 9 cross products of their
// edges.  Projections bound the distance from below along each axis, so a
// wide gap on one axis proves the two apart, and an overlap on all 13
// proves them intersecting; in between (within `margin` of either) the
// exact distance (GJK) decides.  A few dozen flops where GJK takes a
// thousand instructions.
#pragma once

#include "geometry/pose.hpp"

namespace octoprox {

enum class TriangleBoxAnswer { kApart, kIntersecting, kUndecided };

// kApart: along some axis the triangle (corners v, map frame) and the box
// (center, half) lie more than limit + margin apart, so farther than the
// limit.  kIntersecting: along every axis they overlap by more than
// margin, so they intersect (a triangle without area, or an edge parallel
// to a box axis, is never called intersecting here).  Else kUndecided.
TriangleBoxAnswer triangle_box_sat(const Vec3 v[3], const Vec3 &center, const Vec3 &half, double limit,
                                   double margin);

}  // namespace octoprox
