// The distance rules both engines share: the leaf test of a shape against
// an obstacle cell, signed or not, and the keeping of the nearest pair.
// The engines keep their own traversals and bounds.
#pragma once

#include "geometry/aabb.hpp"
#include "narrowphase/shape_distance.hpp"
#include "query/distance_types.hpp"

namespace octoprox {

// The padded shape's distance to the cell, in `out` with its witnesses,
// when it is below `bound` (the search's best so far, or its limit).
// Signed, a touching pair is measured by its penetration, as a negative
// distance, and is kept below the bound too.
bool nearer_pair(const PlacedShape &shape, const Aabb &cell, double bound, bool signed_distance,
                 ShapeCellDistance &out, uint64_t &narrow_tests);

// Takes `pair` as the best when it is the first or nearer than the best;
// returns true then (the caller then sets the best's cell).
bool keep_if_nearer(const PlacedShape &shape, const ShapeCellDistance &pair, DistanceOutcome &best);

}  // namespace octoprox
