// All-or-nothing map updates: the child blocks an update will need are
// taken from the heap before the first cell changes, so running out of
// memory fails the update before it starts, never half way through it.
#pragma once

#include "octree/bounded_tree.hpp"

#include "octree/frame_cells.hpp"

#include <cstddef>

namespace octoprox {

// How many child blocks updating every cell of `cells` takes from the pool: one per node on the
// cells' paths that has no children yet, or does not exist yet, counted
// once per node.  Exact for OctoMap's updateNode, which creates children
// within an existing block and expands a pruned node into one block.
// Counted in `threads` runs of the cells on as many threads (the same
// count whatever the number).
size_t child_blocks_needed(const BoundedOcTree &tree, const FrameCells &cells, size_t threads = 1);

// Makes sure the tree's pool can hand out that many blocks without a heap
// allocation, and the batches an update on `threads` threads draws ahead
// (update_worker.hpp); throws std::bad_alloc, changing nothing in the
// map, if not.
// After the update, the tree's pool gives back what was reserved and not
// used (ChildBlockPool::release_spares): the count is an upper bound, as
// blocks a prune frees are taken again by later cells.
void reserve_update(BoundedOcTree &tree, const FrameCells &cells, size_t threads = 1);

}  // namespace octoprox
