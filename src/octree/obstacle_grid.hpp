// A map's obstacle leaves as a bitmap of bricks, for questions about the
// few cells around a point ("which obstacle cells lie in this key box?")
// without walking down from the root.  A brick is 4x4x4 finest cells, a
// 64-bit word of its obstacle cells (a coarser leaf, a pruned node, is
// expanded into its cells).  An index over the obstacles' key box, 4 bytes
// a brick, points at the words of the non-empty bricks; a byte a brick
// says how far the nearest non-empty brick is, so that most points far
// from every obstacle are answered by one load.
#pragma once

#include "octree/octree_view.hpp"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace octoprox {

enum class GridAnswer { kNo, kYes, kUndecided };

class ObstacleGrid {
public:
    // The grid of the leaves at or above `threshold`; nullptr when its
    // index would take more than max_index_bytes (a huge sparse map).
    static std::unique_ptr<ObstacleGrid> build(const OctreeView &view, float threshold, size_t max_index_bytes);

    float threshold() const { return threshold_; }
    // 1 / the map's resolution: the grid's questions are in key units.
    double cells_per_metre() const { return cells_per_metre_; }

    // A lower bound of the distance, in cells, from any point of the cell
    // at `key` to every obstacle cell: 0 near obstacles; outside the
    // grid's box, the gap to the box.
    int32_t clearance(const int32_t key[3]) const;

    // Calls cell(x, y, z) with the key of every finest obstacle cell in
    // the inclusive key box [lo, hi] until one answers other than kNo, and
    // returns that answer (kNo when none did); kUndecided for a box more
    // than kMaxBricksAcross bricks wide.
    static constexpr int32_t kMaxBricksAcross = 17;

    // The bricks' box: the key of brick (0, 0, 0)'s first cell and the
    // bricks per axis; and the obstacle word of brick b (in bricks from
    // that one, bit x + 4y + 16z), 0 when empty or outside the box.
    const int32_t *origin() const { return origin_; }
    const int32_t *bricks() const { return bricks_; }
    uint64_t word(const int32_t b[3]) const {
        for (int axis = 0; axis < 3; ++axis)
            if (b[axis] < 0 || b[axis] >= bricks_[axis]) return 0;
        const uint32_t at = brick_[(size_t(b[2]) * bricks_[1] + b[1]) * bricks_[0] + b[0]];
        return at == 0 ? 0 : words_[at - 1];
    }
    template <class CellAnswer>
    GridAnswer ask_cells(const int32_t lo[3], const int32_t hi[3], CellAnswer &&cell) const;

private:
    // An obstacle leaf: its first key and its width in cells.
    struct Leaf {
        int32_t key[3];
        int32_t width;
    };
    static constexpr int kMaxBrickGap = 3;  // brick distances kept: 0 (non-empty) to this

    ObstacleGrid() = default;
    // clearance() of a cell outside the grid's box: its gap to the box,
    // where every obstacle cell lies.
    int32_t outside_clearance(const int32_t key[3]) const;
    size_t brick_index(const int32_t cell[3]) const;  // cell relative to origin_
    void fill(const std::vector<Leaf> &leaves);
    void measure_clearance();

    float threshold_ = 0.0f;
    double cells_per_metre_ = 1.0;
    int32_t origin_[3] = {0, 0, 0};  // key of brick (0, 0, 0)'s first cell
    int32_t bricks_[3] = {0, 0, 0};  // bricks per axis
    std::vector<uint32_t> brick_;     // x fastest: 0 empty, else 1 + its word's index
    std::vector<uint64_t> words_;     // bit c (x + 4y + 16z): an obstacle cell
    // Per brick: the Chebyshev distance, in bricks, to the nearest
    // non-empty brick, at most kMaxBrickGap.
    std::vector<uint8_t> clearance_;
};

namespace grid_detail {

// Per axis and range [a, b] of 0..3: the bits of a 4x4x4 word (index
// x + 4y + 16z) whose coordinate on that axis lies in the range.
struct AxisMasks {
    uint64_t mask[3][4][4] = {};
    constexpr AxisMasks() {
        for (int a = 0; a < 4; ++a)
            for (int b = a; b < 4; ++b)
                for (int bit = 0; bit < 64; ++bit) {
                    const int at[3] = {bit & 3, (bit >> 2) & 3, bit >> 4};
                    for (int axis = 0; axis < 3; ++axis)
                        if (at[axis] >= a && at[axis] <= b) mask[axis][a][b] |= uint64_t(1) << bit;
                }
    }
};
inline constexpr AxisMasks kAxisMasks;

// The cells of brick `brick` (in bricks) lying in [lo, hi] (in cells) on
// one axis.
inline uint64_t axis_mask(int axis, int32_t brick, int32_t lo, int32_t hi) {
    const int32_t first = std::max(lo - 4 * brick, 0), last = std::min(hi - 4 * brick, 3);
    return kAxisMasks.mask[axis][first][last];
}

}  // namespace grid_detail

inline int32_t ObstacleGrid::clearance(const int32_t key[3]) const {
    size_t index = 0;
    for (int axis = 2; axis >= 0; --axis) {
        const int32_t brick = (key[axis] - origin_[axis]) >> 2;
        if (brick < 0 || brick >= bricks_[axis]) return outside_clearance(key);
        index = index * size_t(bricks_[axis]) + size_t(brick);
    }
    // A brick k bricks from the nearest non-empty one (on some axis) is
    // 4 (k - 1) cells from every obstacle cell.
    const int32_t gap = clearance_[index];
    return gap > 0 ? 4 * (gap - 1) : 0;
}

inline int32_t ObstacleGrid::outside_clearance(const int32_t key[3]) const {
    int32_t gap = 0;
    for (int axis = 0; axis < 3; ++axis) {
        // The whole cells between the cell and the box, below it or beyond it.
        const int32_t below = origin_[axis] - key[axis] - 1;
        const int32_t above = key[axis] - (origin_[axis] + 4 * bricks_[axis]);
        gap = std::max(gap, std::max(below, above));
    }
    return gap;
}

template <class CellAnswer>
GridAnswer ObstacleGrid::ask_cells(const int32_t lo_key[3], const int32_t hi_key[3], CellAnswer &&cell) const {
    int32_t lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = std::max(lo_key[axis] - origin_[axis], 0);
        hi[axis] = std::min(hi_key[axis] - origin_[axis], 4 * bricks_[axis] - 1);
        if (lo[axis] > hi[axis]) return GridAnswer::kNo;
    }
    const int32_t first_x = lo[0] >> 2, last_x = hi[0] >> 2;
    uint64_t x_masks[kMaxBricksAcross];
    if (last_x - first_x >= kMaxBricksAcross) return GridAnswer::kUndecided;
    for (int32_t bx = first_x; bx <= last_x; ++bx) x_masks[bx - first_x] = grid_detail::axis_mask(0, bx, lo[0], hi[0]);
    for (int32_t bz = lo[2] >> 2; bz <= hi[2] >> 2; ++bz) {
        const uint64_t z_mask = grid_detail::axis_mask(2, bz, lo[2], hi[2]);
        for (int32_t by = lo[1] >> 2; by <= hi[1] >> 2; ++by) {
            const uint64_t yz_mask = z_mask & grid_detail::axis_mask(1, by, lo[1], hi[1]);
            const uint32_t *row = &brick_[(size_t(bz) * bricks_[1] + by) * bricks_[0]];
            for (int32_t bx = first_x; bx <= last_x; ++bx) {
                if (row[bx] == 0) continue;
                uint64_t cells = words_[row[bx] - 1] & yz_mask & x_masks[bx - first_x];
                for (; cells != 0; cells &= cells - 1) {
                    const int c = __builtin_ctzll(cells);
                    const GridAnswer answer = cell(origin_[0] + 4 * bx + (c & 3), origin_[1] + 4 * by + ((c >> 2) & 3),
                                                   origin_[2] + 4 * bz + (c >> 4));
                    if (answer != GridAnswer::kNo) return answer;
                }
            }
        }
    }
    return GridAnswer::kNo;
}

}  // namespace octoprox
