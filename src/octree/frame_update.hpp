// A frame's cells into the map in one depth-first pass.
//
// The result is the map OctoMap's updateNode(key, hit or miss, lazy_eval =
// false) gives when called once per cell: a cell whose leaf is already
// clamped in the update's direction is left alone (OctoMap's early exit,
// which also leaves its path unpruned), pruned nodes are expanded on the
// way down, and every node on a changed path is pruned or has its
// occupancy (and obstacle box) recomputed on the way up.  The cells come
// in Morton order, so each node on the shared paths is visited once per
// frame instead of once per cell, and a node pruned by one cell is never
// expanded again by the next one.
#pragma once

#include "octree/frame_cells.hpp"
#include "octree/point_extent.hpp"

#include <vector>

namespace octoprox {

class BoundedOcTree;

// Call inside a BoundsScope, after reserve_update.  `extents` holds one
// entry per hit cell, ascending by code (FrameRays::hit_extents).  A hit
// leaf's point extent grows by the frame's points when it has one, starts
// from them when the leaf was not occupied (log-odds below
// `occupied_log_odds`) before, and stays absent (the whole cube) on a leaf
// that was occupied without one (read from a file); a missed leaf that
// ends below the threshold loses its extent.
void apply_frame_cells(BoundedOcTree &tree, const FrameCells &cells, const std::vector<CellExtent> &extents,
                       float occupied_log_odds);

}  // namespace octoprox
