// SensorOctree's edits of whole regions: clearing, decay and cropping.
#include "octree/sensor_octree.hpp"

#include "octree/bounded_tree.hpp"
#include "octree/decay.hpp"
#include "octree/region_edit.hpp"

#include <algorithm>

namespace octoprox {
namespace {

// The box of a key range, metres, as the known bounds hold it.
Aabb box_of(const CellRange &keys, double resolution) {
    Aabb box;
    for (int axis = 0; axis < 3; ++axis) {
        box.lo[axis] = static_cast<double>(keys.lo[axis] - kKeyCenter) * resolution;
        box.hi[axis] = static_cast<double>(keys.hi[axis] - kKeyCenter + 1) * resolution;
    }
    return box;
}

// Whether removing the cells of `removed` may shrink `known`: it reaches
// within a cell of one of its faces (a cell of slack covers rounding).
bool reaches_faces(const Aabb &removed, const Aabb &known, double resolution) {
    for (int axis = 0; axis < 3; ++axis)
        if (removed.lo[axis] <= known.lo[axis] + resolution || removed.hi[axis] >= known.hi[axis] - resolution)
            return true;
    return false;
}

}  // namespace

void SensorOctree::update_known_bounds(const EditedCubes &edited) {
    const double res = params_.resolution;
    if (!edited.removed.empty() && reaches_faces(box_of(edited.removed, res), known_bounds_, res)) {
        recompute_known_bounds();
        return;
    }
    if (!edited.set_free.empty()) {
        const Aabb added = box_of(edited.set_free, res);
        known_bounds_.grow(added.lo);
        known_bounds_.grow(added.hi);
    }
}

void SensorOctree::clear_region(const CubeRegion &region, bool to_free) {
    RegionEdit edit;
    edit.to_free = to_free;
    edit.free_value = tree_->getClampingThresMinLog();
    const size_t blocks = region_edit_blocks(*tree_, region, edit);
    tree_->child_blocks().reserve(blocks);
    ++generation_;
    EditedCubes edited;
    {
        const BoundsScope scope(occupied_log_odds_);
        edited = apply_region_edit(*tree_, region, edit);
    }
    tree_->child_blocks().release_spares();
    update_known_bounds(edited);
}

void SensorOctree::decay(double amount) {
    if (!(amount > 0.0) || tree_->getRoot() == nullptr) return;
    ++generation_;
    bool removed = false;
    {
        const BoundsScope scope(occupied_log_odds_);
        removed = decay_cells(*tree_, amount, occupied_log_odds_);
    }
    if (removed) recompute_known_bounds();
}

// The edit and the move into fresh slabs take all their memory first, so
// a crop that runs out of it changes nothing.
void SensorOctree::crop(const CellRange &keep) {
    const CellRangeRegion outside(keep, true);
    RegionEdit edit;  // to unknown
    const size_t blocks = region_edit_blocks(*tree_, outside, edit);
    const size_t kept = blocks_after_removal(*tree_, outside);
    ChildBlockPool &pool = tree_->child_blocks();
    constexpr size_t kSlabBlocks = (size_t{64} << 10) / ChildBlockPool::kBlockBytes;
    const size_t idle = pool.blocks_idle() + pool.blocks_in_use() - std::min(kept, pool.blocks_in_use());
    ChildBlockPool fresh;
    const bool compact = idle > kSlabBlocks && idle > kept / 3;
    if (compact) fresh.reserve(kept);
    pool.reserve(blocks);
    ++generation_;
    EditedCubes edited;
    {
        const BoundsScope scope(occupied_log_odds_);
        edited = apply_region_edit(*tree_, outside, edit);
    }
    pool.release_spares();
    update_known_bounds(edited);
    if (compact) tree_->compact_blocks(fresh);
}

}  // namespace octoprox
