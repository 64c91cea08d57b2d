#include "octree/obstacle_grid.hpp"
#include "octree/obstacle_grid_cache.hpp"

#include <algorithm>

namespace octoprox {
namespace {

// The leaves at or above the threshold; a subtree whose value (its
// children's maximum) is below it holds none.  Recursion depth is bounded
// by kTreeDepth.
template <class Leaf>
void collect_leaves(const OctreeView &view, OctreeView::NodeRef node, const CellKey &cell, float threshold,
                    std::vector<Leaf> &out) {
    if (view.log_odds(node) < threshold) return;
    if (!view.has_children(node)) {
        out.push_back({{cell.key[0], cell.key[1], cell.key[2]}, cell.width_in_cells()});
        return;
    }
    for (int i = 0; i < 8; ++i)
        if (OctreeView::NodeRef child = view.child(node, i)) collect_leaves(view, child, cell.child(i), threshold, out);
}

// Each leaf's cells (relative to origin_), a brick's or one cell's worth
// at a time: all the cells of a brick the leaf covers, else the leaf's own
// (a leaf is aligned to its width); part(cell, bits of its brick's word).
template <class Part>
void for_each_part(const int32_t key[3], int32_t width, const int32_t origin[3], Part &&part) {
    const int32_t step = std::min<int32_t>(width, 4);
    for (int32_t z = 0; z < width; z += step)
        for (int32_t y = 0; y < width; y += step)
            for (int32_t x = 0; x < width; x += step) {
                const int32_t at[3] = {key[0] - origin[0] + x, key[1] - origin[1] + y, key[2] - origin[2] + z};
                uint64_t bits = ~uint64_t(0);
                if (width < 4) {
                    const int first = (at[0] & 3) | ((at[1] & 3) << 2) | ((at[2] & 3) << 4);
                    bits = (width == 2 ? uint64_t(0x330033) : uint64_t(1)) << first;  // a 2x2x2 or 1x1x1 cube
                }
                part(at, bits);
            }
}

}  // namespace

std::unique_ptr<ObstacleGrid> ObstacleGrid::build(const OctreeView &view, float threshold, size_t max_index_bytes) {
    std::vector<Leaf> leaves;
    if (OctreeView::NodeRef root = view.root()) collect_leaves(view, root, CellKey{}, threshold, leaves);
    std::unique_ptr<ObstacleGrid> grid(new ObstacleGrid);
    grid->threshold_ = threshold;
    grid->cells_per_metre_ = 1.0 / view.resolution();
    if (leaves.empty()) return grid;

    int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {INT32_MIN, INT32_MIN, INT32_MIN};
    for (const Leaf &leaf : leaves)
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = std::min(lo[axis], leaf.key[axis]);
            hi[axis] = std::max(hi[axis], leaf.key[axis] + leaf.width - 1);
        }
    size_t brick_count = 1;
    for (int axis = 0; axis < 3; ++axis) {
        grid->origin_[axis] = lo[axis] & ~3;  // keys are >= 0
        grid->bricks_[axis] = (hi[axis] - grid->origin_[axis]) / 4 + 1;
        brick_count *= size_t(grid->bricks_[axis]);
    }
    if (brick_count > max_index_bytes / (sizeof(uint32_t) + 1)) return nullptr;
    grid->fill(leaves);
    return grid;
}

size_t ObstacleGrid::brick_index(const int32_t cell[3]) const {
    return (size_t(cell[2] >> 2) * size_t(bricks_[1]) + size_t(cell[1] >> 2)) * size_t(bricks_[0]) + size_t(cell[0] >> 2);
}

// The non-empty bricks first, each given its word, then the cells' bits.
void ObstacleGrid::fill(const std::vector<Leaf> &leaves) {
    brick_.assign(size_t(bricks_[0]) * size_t(bricks_[1]) * size_t(bricks_[2]), 0);
    for (const Leaf &leaf : leaves)
        for_each_part(leaf.key, leaf.width, origin_, [&](const int32_t at[3], uint64_t) { brick_[brick_index(at)] = 1; });
    uint32_t next = 0;
    for (uint32_t &brick : brick_)
        if (brick != 0) brick = ++next;
    words_.assign(next, 0);
    for (const Leaf &leaf : leaves)
        for_each_part(leaf.key, leaf.width, origin_,
                      [&](const int32_t at[3], uint64_t bits) { words_[brick_[brick_index(at)] - 1] |= bits; });
    measure_clearance();
}

// Chebyshev distances on the brick grid, capped: a non-empty brick is 0,
// and each of kMaxBrickGap - 1 dilations by one brick (a 3x3x3 box, one
// axis at a time) reaches the bricks one farther.
void ObstacleGrid::measure_clearance() {
    const size_t n[3] = {size_t(bricks_[0]), size_t(bricks_[1]), size_t(bricks_[2])};
    const size_t stride[3] = {1, n[0], n[0] * n[1]};
    std::vector<uint8_t> reached(brick_.size()), grown;
    clearance_.assign(brick_.size(), uint8_t(kMaxBrickGap));
    for (size_t at = 0; at < brick_.size(); ++at)
        if (brick_[at] != 0) reached[at] = 1, clearance_[at] = 0;
    for (uint8_t gap = 1; gap < kMaxBrickGap; ++gap) {
        for (int axis = 0; axis < 3; ++axis) {
            grown = reached;
            for (size_t at = 0; at < reached.size(); ++at) {
                if (!reached[at]) continue;
                const size_t along = at / stride[axis] % n[axis];
                if (along > 0) grown[at - stride[axis]] = 1;
                if (along + 1 < n[axis]) grown[at + stride[axis]] = 1;
            }
            reached.swap(grown);
        }
        for (size_t at = 0; at < reached.size(); ++at)
            if (reached[at] && clearance_[at] > gap) clearance_[at] = gap;
    }
}

// A grid's index may take this much (5 bytes a brick of 64 cells: a box
// of 2^30 cells); a larger map's spheres take the descent alone.
constexpr size_t kMaxGridIndexBytes = size_t(80) << 20;

std::shared_ptr<const ObstacleGrid> ObstacleGridCache::get(const OctreeView &view, uint64_t generation,
                                                           float threshold) const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!built_ || generation_ != generation || threshold_ != threshold) {
        built_ = false;
        grid_ = ObstacleGrid::build(view, threshold, kMaxGridIndexBytes);
        built_ = true;
        generation_ = generation;
        threshold_ = threshold;
    }
    return grid_;
}

}  // namespace octoprox
