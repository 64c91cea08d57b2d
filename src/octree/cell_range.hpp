// A box of the map as finest-cell keys: the cells holding a point of a
// closed box [min, max] (map frame), found as OctoMap finds a point's cell
// (coordToKey: floor(x / resolution), a point on a face between two cells
// in the upper one), so a box face on a cell face takes the cell above it.
// The same rule serves clearing, cropping and bounded inserts, so they
// agree with one another and with opx_octree_classify at every face.
#pragma once

#include "octree/octree_view.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace octoprox {

struct CellRange {
    int32_t lo[3] = {0, 0, 0};
    int32_t hi[3] = {-1, -1, -1};  // inclusive; lo > hi on an axis: empty

    bool empty() const { return lo[0] > hi[0] || lo[1] > hi[1] || lo[2] > hi[2]; }
    bool contains(const uint32_t key[3]) const {
        for (int axis = 0; axis < 3; ++axis)
            if (static_cast<int32_t>(key[axis]) < lo[axis] || static_cast<int32_t>(key[axis]) > hi[axis]) return false;
        return true;
    }
    // Whether every finest cell of the cube is inside; whether one is.
    bool holds_cube(const CellKey &cube) const {
        const int32_t width = cube.width_in_cells();
        for (int axis = 0; axis < 3; ++axis)
            if (cube.key[axis] < lo[axis] || cube.key[axis] + width - 1 > hi[axis]) return false;
        return true;
    }
    bool meets_cube(const CellKey &cube) const {
        const int32_t width = cube.width_in_cells();
        for (int axis = 0; axis < 3; ++axis)
            if (cube.key[axis] > hi[axis] || cube.key[axis] + width - 1 < lo[axis]) return false;
        return true;
    }
};

// The key of coordinate x (metres) as OctoMap's coordToKey computes it,
// clamped to one below the cube (-1) and one above it (2^16): x need not
// lie in the map, and may be infinite.
inline int32_t clamped_key(double x, double resolution) {
    const double cells = std::floor(x * (1.0 / resolution));
    const double limit = kKeyCenter + 1.0;
    return static_cast<int32_t>(std::max(-limit, std::min(limit, cells))) + kKeyCenter;
}

// The cells of the closed box [min, max]; min <= max on every axis.
inline CellRange cell_range_of_box(const double min[3], const double max[3], double resolution) {
    CellRange range;
    constexpr int32_t kLastKey = 2 * kKeyCenter - 1;
    for (int axis = 0; axis < 3; ++axis) {
        range.lo[axis] = std::max(0, clamped_key(min[axis], resolution));
        range.hi[axis] = std::min(kLastKey, clamped_key(max[axis], resolution));
    }
    return range;
}

}  // namespace octoprox
