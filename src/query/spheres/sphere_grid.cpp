#include "query/spheres/sphere_grid.hpp"

#include "narrowphase/narrow_phase.hpp"

namespace octoprox {
namespace {

// The cells read around a sphere: those within its touch limit and this
// much more (key units), far more than any rounding of the centre.
constexpr double kKeyReach = 1e-6;
// Cells a sphere's key box may span on an axis: a wider sphere is left
// to the descent, which prunes far more of its cells at once.
constexpr int kMaxSpan = 64;

}  // namespace

GridAnswer sphere_on_grid(const ObstacleGrid &grid, const Vec3 &center, double radius, bool point_extents) {
    // Most spheres far from every obstacle are answered by one byte.
    if (sphere_surely_clear(grid, center, radius)) return GridAnswer::kNo;
    const double per_cell = grid.cells_per_metre();
    int32_t lo[3], hi[3], key[3];
    double at[3];  // the centre in key units
    const double reach = (radius + kTouchTolerance) * per_cell + kKeyReach;
    for (int axis = 0; axis < 3; ++axis) {
        at[axis] = center[axis] * per_cell + kKeyCenter;
        // The cells within reach (the keys are positive: truncation is floor).
        const double low = at[axis] - reach, high = at[axis] + reach;
        if (!(low >= 0.0 && high < 65536.0 && high - low < kMaxSpan - 1)) return GridAnswer::kUndecided;
        lo[axis] = static_cast<int32_t>(low);
        hi[axis] = static_cast<int32_t>(high);
        key[axis] = static_cast<int32_t>(at[axis]);
    }
    const double limit = (radius + kTouchTolerance) * per_cell + kGridKeyMargin;
    // Surely touching: the ball itself (not only its tolerance) reaches
    // into the cell, so the sphere's box overlaps the cell as well.
    const double ball = radius * per_cell;
    const double sure_in = ball > kGridKeyMargin ? (ball - kGridKeyMargin) * (ball - kGridKeyMargin) : -1.0;
    const double sure_out = limit * limit;
    return grid.ask_cells(lo, hi, [&](int32_t x, int32_t y, int32_t z) {
        // The squared distance, in key units, from the centre to the cell.
        const int32_t cell[3] = {x, y, z};
        double d2 = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            const double gap = cell[axis] < key[axis]   ? at[axis] - (cell[axis] + 1)
                               : cell[axis] > key[axis] ? cell[axis] - at[axis]
                                                        : 0.0;
            d2 += gap * gap;
        }
        if (d2 > sure_out) return GridAnswer::kNo;
        // A point extent lies inside its cell: the cell only says "maybe".
        if (d2 < sure_in && !point_extents) return GridAnswer::kYes;
        return GridAnswer::kUndecided;
    });
}

}  // namespace octoprox
