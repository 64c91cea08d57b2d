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

#include <cstddef>
#include <cstdint>
#include <vector>

namespace octoprox {

class BoundedOcTree;

// How many threads apply_frame_cells uses for `cells` with at most
// `max_threads` (0: one per hardware thread): one for small frames.
size_t frame_update_threads(const FrameCells &cells, uint32_t max_threads);

// Call inside a BoundsScope, after reserve_update with the same `threads`.
// `extents` holds one entry per hit cell, ascending by code
// (FrameRays::hit_extents).  A hit leaf's point extent grows by the
// frame's points when it has one, starts from them when the leaf was not
// occupied (log-odds below `occupied_log_odds`) before, and stays absent
// (the whole cube) on a leaf that was occupied without one (read from a
// file); a missed leaf that ends below the threshold loses its extent.
// With more than one thread the subtrees of the frame's cells are updated
// in parallel; the map is the same cell for cell.
void apply_frame_cells(BoundedOcTree &tree, const FrameCells &cells, const std::vector<CellExtent> &extents,
                       float occupied_log_odds, size_t threads = 1);

// The parallel update with the subtrees at `split_depth` (1 to 15) below
// the root, whatever the frame's size (apply_frame_cells chooses it from
// the frame's box; the tests try every depth).
void apply_frame_cells_split(BoundedOcTree &tree, const FrameCells &cells, const std::vector<CellExtent> &extents,
                             float occupied_log_odds, size_t threads, int split_depth);

}  // namespace octoprox
