// A sphere against the map's obstacle grid (octree/obstacle_grid.hpp): the
// cells around it read from the grid's words, each placed in key units,
// instead of a descent from the root.  The answer is the descent's
// (sphere_query.hpp) whenever it is not kUndecided: a cell within 1e-8 of
// a cell's width of the touch limit, a point extent, a sphere at the map's
// faces or wider than 60 cells leave the answer to the descent.
#pragma once

#include "geometry/aabb.hpp"
#include "narrowphase/narrow_phase.hpp"
#include "octree/obstacle_grid.hpp"

namespace octoprox {

// Cells are placed in key units (a cell is [k, k + 1] on each axis), where
// the map's coordinates carry rounding of at most 1e-11: a cell farther
// than this from the touch limit is decided there, for the descent's tests
// on its boxes decide it the same way.
constexpr double kGridKeyMargin = 1e-8;

// Whether the grid alone shows the sphere (radius with padding) farther
// than its touch limit from every obstacle: the clearance of the cell
// holding its centre exceeds its reach.  Inline, for a robot of spheres
// asks it of every sphere, and most spheres are far from obstacles.
inline bool sphere_surely_clear(const ObstacleGrid &grid, const Vec3 &center, double radius) {
    const double per_cell = grid.cells_per_metre();
    int32_t key[3];
    for (int axis = 0; axis < 3; ++axis) {
        const double at = center[axis] * per_cell + kKeyCenter;
        if (!(at >= 0.0 && at < 65536.0)) return false;
        key[axis] = static_cast<int32_t>(at);  // at >= 0: truncation is floor
    }
    return grid.clearance(key) > (radius + kTouchTolerance) * per_cell + kGridKeyMargin;
}

// radius: the sphere's (padding included); touching within kTouchTolerance
// counts, as everywhere.
GridAnswer sphere_on_grid(const ObstacleGrid &grid, const Vec3 &center, double radius, bool point_extents);

}  // namespace octoprox
