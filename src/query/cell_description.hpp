// What queries report of the cell a shape met, the same for both engines:
// an octree cell (its key, and its log-odds unless it is a cube of unknown
// space) or one of a caller's boxes.
#pragma once

#include "geometry/aabb.hpp"
#include "octree/octree_view.hpp"
#include "query/collision_types.hpp"
#include "query/distance_types.hpp"

namespace octoprox {

class SensorOctree;

struct CellSummary {
    Vec3 center = Vec3::Zero();  // map frame
    double size = 0.0;           // edge of the cube (a caller's box: its longest edge)
    int cell_class = 0;
    double probability = 0.0;
};

// Unknown space is class unknown with probability 0.5; a known cell is
// classified by the tree's thresholds.
CellSummary describe_cell(const SensorOctree &tree, const CellKey &key, bool unknown, float log_odds);
// A caller's box counts as occupied, probability 1.
CellSummary describe_caller_box(const Aabb &box);

void set_cell(Contact &contact, const CellSummary &cell);
// The nearest pair's cell, for describe_cell later (log-odds 0 for unknown).
void set_cell(DistanceOutcome &best, const CellKey &key, bool unknown, float log_odds);

}  // namespace octoprox
