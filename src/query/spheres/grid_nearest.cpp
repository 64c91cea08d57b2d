#include "query/spheres/grid_nearest.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace octoprox {
namespace {

// The keys [lo, lo + width) as a box, its faces as cell_box places them.
Aabb key_box(const int32_t lo[3], int32_t width, double resolution) {
    Aabb box;
    for (int axis = 0; axis < 3; ++axis) {
        box.lo[axis] = static_cast<double>(lo[axis] - kKeyCenter) * resolution;
        box.hi[axis] = static_cast<double>(lo[axis] + width - kKeyCenter) * resolution;
    }
    return box;
}

class Rings {
public:
    Rings(const ObstacleGrid &grid, double resolution, const Vec3 &at) : grid_(grid), resolution_(resolution), at_(at) {}

    // The centre's brick (relative to the grid's first); false outside
    // the map's keys.
    bool locate() {
        const double per_cell = 1.0 / resolution_;
        for (int axis = 0; axis < 3; ++axis) {
            const double at = at_[axis] * per_cell + kKeyCenter;
            const double key = std::floor(at);
            if (!(key >= 0.0 && key < 65536.0)) return false;
            key_[axis] = static_cast<int32_t>(key);
            center_[axis] = (key_[axis] - grid_.origin()[axis]) >> 2;
            // The centre's gap to its brick's nearest face, in cells.
            const double brick_lo = grid_.origin()[axis] + 4.0 * center_[axis];
            inset_ = std::min({inset_, at - brick_lo, brick_lo + 4.0 - at});
        }
        inset_ = std::max(inset_, 0.0);
        return true;
    }

    // The first ring that may hold an obstacle: the grid's clearance says
    // the bricks within gap - 1 of the centre's are empty (clearance
    // 4 (gap - 1) cells); outside the grid's box, its first ring.
    int32_t first_obstacle_ring() const {
        const int32_t outside = first_ring();
        if (outside > 0) return outside;
        const int32_t clearance = grid_.clearance(key_);
        return clearance > 0 ? clearance / 4 + 1 : 0;
    }

    // The first ring holding a brick of the grid.
    int32_t first_ring() const {
        int32_t ring = 0;
        for (int axis = 0; axis < 3; ++axis)
            ring = std::max({ring, -center_[axis], center_[axis] - (grid_.bricks()[axis] - 1)});
        return ring;
    }

    // Calls brick(word, first key) for the grid's bricks whose word is
    // wanted, ring by ring from `first`,
    // skipping bricks whose box is not nearer than the best, until a
    // ring's lower bound (4 (s - 1) cells) reaches the best or `last`.
    template <class Wanted, class Brick>
    void visit(int32_t first, int32_t last, NearestPiece &best, Wanted &&wanted, Brick &&brick) const {
        for (int32_t s = first; s <= last; ++s) {
            // Ring s lies beyond the 2s - 1 bricks around the centre's.
            const double gap = (4.0 * (s - 1) + inset_) * resolution_;
            if (s >= 1 && !(gap * gap < best.squared)) return;
            // Only the bricks within the best distance's key box, and in the grid.
            int32_t lo[3], hi[3];
            if (!reach_box(best.squared, lo, hi)) return;
            const int32_t z0 = std::max(-s, lo[2]), z1 = std::min(s, hi[2]);
            const int32_t y0 = std::max(-s, lo[1]), y1 = std::min(s, hi[1]);
            const int32_t x0 = std::max(-s, lo[0]), x1 = std::min(s, hi[0]);
            for (int32_t dz = z0; dz <= z1; ++dz)
                for (int32_t dy = y0; dy <= y1; ++dy) {
                    const bool face = std::abs(dz) == s || std::abs(dy) == s;
                    for (int32_t dx = face ? x0 : -s; dx <= x1; dx += face || s == 0 ? 1 : 2 * s) {
                        if (dx < x0) continue;
                        const int32_t b[3] = {center_[0] + dx, center_[1] + dy, center_[2] + dz};
                        const uint64_t word = grid_.word(b);
                        if (!wanted(word)) continue;
                        const int32_t first_key[3] = {grid_.origin()[0] + 4 * b[0], grid_.origin()[1] + 4 * b[1],
                                                      grid_.origin()[2] + 4 * b[2]};
                        if (!(squared_to(at_, key_box(first_key, 4, resolution_)) < best.squared)) continue;
                        brick(word, first_key, best);
                    }
                }
        }
    }

    // The nearest cell of `cells` (bits of the brick whose first key is
    // lo), offered: per axis the gaps to the brick's four layers, squared,
    // so a cell costs three loads and two additions; the winner's box is
    // then measured as every piece is.
    void offer_cells(uint64_t cells, const int32_t lo[3], NearestPiece &best) const {
        double gap[3][4];
        for (int axis = 0; axis < 3; ++axis)
            for (int i = 0; i < 4; ++i) {
                const double low = static_cast<double>(lo[axis] + i - kKeyCenter) * resolution_;
                const double high = static_cast<double>(lo[axis] + i + 1 - kKeyCenter) * resolution_;
                const double g = std::max({low - at_[axis], at_[axis] - high, 0.0});
                gap[axis][i] = g * g;
            }
        double nearest = best.squared;
        int winner = -1;
        for (; cells != 0; cells &= cells - 1) {
            const int c = __builtin_ctzll(cells);
            const double squared = gap[0][c & 3] + gap[1][(c >> 2) & 3] + gap[2][c >> 4];
            if (squared < nearest) nearest = squared, winner = c;
        }
        if (winner < 0) return;
        const int32_t key[3] = {lo[0] + (winner & 3), lo[1] + ((winner >> 2) & 3), lo[2] + (winner >> 4)};
        best.offer(at_, key_box(key, 1, resolution_));
    }

    const ObstacleGrid &grid() const { return grid_; }
    double resolution() const { return resolution_; }
    const Vec3 &at() const { return at_; }

private:
    // The bricks (offsets from the centre's) of the grid that hold keys
    // within sqrt(squared) of the centre (and a cell more, for rounding);
    // false when none does.
    bool reach_box(double squared, int32_t lo[3], int32_t hi[3]) const {
        const double reach = std::sqrt(squared) / resolution_ + 1.0;
        const double per_cell = 1.0 / resolution_;
        for (int axis = 0; axis < 3; ++axis) {
            const double at = at_[axis] * per_cell + kKeyCenter - grid_.origin()[axis];
            const double low = std::max(std::floor((at - reach) / 4.0), -1.0);
            const double high = std::min(std::floor((at + reach) / 4.0), double(grid_.bricks()[axis]));
            lo[axis] = std::max(static_cast<int32_t>(low), 0) - center_[axis];
            hi[axis] = std::min(static_cast<int32_t>(high), grid_.bricks()[axis] - 1) - center_[axis];
            if (lo[axis] > hi[axis]) return false;
        }
        return true;
    }

    const ObstacleGrid &grid_;
    double resolution_;
    const Vec3 &at_;
    int32_t center_[3] = {0, 0, 0};
    int32_t key_[3] = {0, 0, 0};
    double inset_ = 4.0;
};

}  // namespace

bool grid_nearest_obstacle(const ObstacleGrid &grid, double resolution, const Vec3 &at, double bound_squared,
                           NearestPiece &out) {
    const double reach = std::sqrt(bound_squared) / resolution;
    if (!(reach <= kGridSearchCells)) return false;
    Rings rings(grid, resolution, at);
    if (!rings.locate()) return false;
    out = NearestPiece{};
    out.squared = bound_squared;
    // Ring s's bricks are at least 4 (s - 1) cells away: none beyond this.
    const int32_t last = static_cast<int32_t>(reach / 4.0) + 2;
    rings.visit(
        rings.first_obstacle_ring(), last, out, [](uint64_t word) { return word != 0; },
        [&](uint64_t word, const int32_t lo[3], NearestPiece &best) { rings.offer_cells(word, lo, best); });
    return true;
}

NearestPiece grid_nearest_free(const ObstacleGrid &grid, double resolution, const Vec3 &at) {
    NearestPiece best;
    // Beyond the grid's box every cell is free: the nearest point of its faces.
    int32_t lo[3];
    for (int axis = 0; axis < 3; ++axis) lo[axis] = grid.origin()[axis];
    const Aabb box = key_box(lo, 0, resolution);
    Aabb whole = box;
    for (int axis = 0; axis < 3; ++axis)
        whole.hi[axis] = static_cast<double>(lo[axis] + 4 * grid.bricks()[axis] - kKeyCenter) * resolution;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            Aabb face{at, at};
            face.lo[axis] = face.hi[axis] = side == 0 ? whole.lo[axis] : whole.hi[axis];
            best.offer(at, face);
        }
    Rings rings(grid, resolution, at);
    if (!rings.locate()) return best;  // not reached: the centre is in a cell of the grid
    rings.visit(
        0, INT32_MAX - 1, best, [](uint64_t word) { return ~word != 0; },
        [&](uint64_t word, const int32_t lo_key[3], NearestPiece &near) {
            if (word == 0) near.offer(at, key_box(lo_key, 4, resolution));
            else rings.offer_cells(~word, lo_key, near);
        });
    return best;
}

}  // namespace octoprox
