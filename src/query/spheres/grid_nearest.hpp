// The two searches of map_nearest.hpp read from the map's obstacle grid
// (octree/obstacle_grid.hpp) instead of the octree, for obstacles that are
// whole cells with unknown space free: rings of bricks around the centre's
// brick, nearest first, until a ring's lower bound passes the best.  The
// grid holds exactly the finest cells of the obstacle leaves and each
// cell's box is computed as the octree's (cell_box), so the distances are
// the octree searches', bit for bit; among equidistant pieces the first
// in ring order wins.
#pragma once

#include "octree/obstacle_grid.hpp"
#include "query/spheres/map_nearest.hpp"

namespace octoprox {

// Searches reaching farther than this (cells) are left to the octree.
constexpr double kGridSearchCells = 64.0;

// As nearest_obstacle; false when the grid leaves it to the octree (a
// centre outside the map's keys, a bound beyond kGridSearchCells).
bool grid_nearest_obstacle(const ObstacleGrid &grid, double resolution, const Vec3 &at, double bound_squared,
                           NearestPiece &out);

// As nearest_free, for a centre in an obstacle cell of the grid.
NearestPiece grid_nearest_free(const ObstacleGrid &grid, double resolution, const Vec3 &at);

}  // namespace octoprox
