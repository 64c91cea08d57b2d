// Distance between a cylinder and a cell (an axis-aligned box), exact
// without iterating on the curved surface where it can be.
//
// GJK converges slowly on a cylinder (some 30-40 iterations to its
// tolerance: each support point on the rim only approximates the closest
// one), while the nearest point of a cylinder usually lies on a flat part
// of it, where the answer is a polytope's:
// - beyond a cap: the whole box lies past the cap's plane and the box's
//   vertex nearest that plane projects inside the cap's disk; the distance
//   is that vertex's height above the plane;
// - beside the round side: the nearest point of the axis segment to the
//   box (GJK between two polytopes: exact, a few iterations) is inside the
//   segment, so the pair's direction is square to the axis; the distance
//   is the segment's minus the radius (the cylinder lies inside that
//   capsule, and the capsule's nearest point is on the cylinder).
// Anything else (the rim, overlap) goes to GJK on the cylinder.
#pragma once

#include "geometry/gjk.hpp"

namespace octoprox {

// How cylinder_cell_distance answered (tests check that each way is used).
enum class CylinderPath { kCap, kSide, kGjk };

// The same contract as gjk_cell_distance for a query whose shape is a
// cylinder (query.shape->kind == kCylinder): the distance, or a lower bound
// above stop_above, and witness points.
GjkResult cylinder_cell_distance(const GjkQuery &query, CylinderPath *path = nullptr);

}  // namespace octoprox
