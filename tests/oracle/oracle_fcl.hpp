// Distances that need a curved shape: a cylinder vs a cell.
//
// FCL measures them (fcl::distance, Cylinderd vs Boxd) with BOTH its GJK
// solvers, GST_INDEP and GST_LIBCCD, at a tight tolerance.  Two independent
// implementations that agree are trusted; when they do not (FCL's GST_INDEP
// is wrong by millimetres on ~0.1% of box-box pairs, see
// test_oracle_geometry), the distance is bracketed exactly between an
// inscribed and a circumscribed prism (exact polytope distances).  GJK
// converges on a curved surface only up to its tolerance, so the tests treat
// pairs whose distance is within kCurvedAmbiguity of the threshold as
// ambiguous.
#pragma once

#include "oracle_geometry.hpp"

#include <cstdint>

namespace oracle {

// Half-width of the band around the threshold where a cylinder decision is
// not compared (counted and printed instead).
constexpr double kCurvedAmbiguity = 1e-5;

// A solid cylinder: `axes` columns are its frame (z = axis) in the map frame.
struct Cylinder {
    Vec3 center = Vec3::Zero();
    Mat3 axes = Mat3::Identity();
    double radius = 0.0;
    double length = 0.0;  // FULL length along the axis
};

// The distance, or when they intersect: -1 when they do so by more than the
// ambiguity band (they still intersect when both shrink by twice the band),
// else 0.
double cylinder_cell_distance(const Cylinder &cylinder, const Cell &cell);

// How often the two FCL solvers disagreed (prism brackets decided), and how
// often the brackets could not be made narrower than the ambiguity band.
struct CurvedStats {
    uint64_t measured = 0, disagreements = 0, unresolved = 0;
};
CurvedStats curved_stats();

// A prism of `sides` sides around the cylinder's axis, its vertices at
// distance `rim` from the axis: inscribed for rim = radius, circumscribed for
// rim = radius / cos(pi / sides).
Polytope cylinder_prism(const Cylinder &cylinder, int sides, double rim);

// The distance (0 when intersecting) by FCL for two polytopes, with one
// solver: only used to check the exact oracle (and FCL).
double fcl_box_cell_distance(const OrientedBox &box, const Cell &cell, bool libccd);

}  // namespace oracle
