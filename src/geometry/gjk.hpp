// Distance between a cell (an axis-aligned box) and a convex piece, or
// between two convex pieces, by GJK on their Minkowski difference, in
// double precision.
//
// Between two polytopes (box, segment, triangle, hull, point) GJK ends on
// the exact closest features, so distances are exact to rounding (~1e-15
// relative).  A cylinder is curved: there GJK stops when an iteration gains
// less than kGjkRelativeTolerance of the squared distance, which bounds the
// error by about 1e-7 of the distance (documented in docs/geometry.md).
#pragma once

#include "geometry/convex.hpp"
#include "geometry/simplex.hpp"

#include <limits>

namespace octoprox {

constexpr double kGjkRelativeTolerance = 1e-14;

struct GjkQuery {
    Vec3 cell_center = Vec3::Zero();
    Vec3 cell_half = Vec3::Zero();
    const Convex *shape = nullptr;
    // Early exits: stop as soon as the distance is proven above stop_above
    // (the result is then a lower bound above it), or found at or below
    // stop_below.  Defaults compute the exact distance.
    double stop_above = std::numeric_limits<double>::infinity();
    double stop_below = -1.0;
};

struct GjkResult {
    double distance = 0.0;  // 0 when the two intersect
    bool intersecting = false;
    Vec3 on_cell = Vec3::Zero();   // witness points, map frame (valid when
    Vec3 on_shape = Vec3::Zero();  // not intersecting and not stopped above)
    // When intersecting: GJK's last simplex, a tetrahedron holding the
    // origin (size 4), or smaller when the origin lies on its boundary.
    Simplex simplex;
};

GjkResult gjk_cell_distance(const GjkQuery &query);

// Two convex pieces, with the same early exits.
struct GjkPairQuery {
    const Convex *a = nullptr;
    const Convex *b = nullptr;
    // About the size of the two pieces (metres): distances below 1e-13 of
    // it are rounding noise, the pieces touch.
    double scale = 1.0;
    double stop_above = std::numeric_limits<double>::infinity();
    double stop_below = -1.0;
};

// As gjk_cell_distance, with on_shape on `a` and on_cell on `b`; when
// intersecting, the simplex's s points are a's and its c points b's.
GjkResult gjk_pair_distance(const GjkPairQuery &query);

}  // namespace octoprox
