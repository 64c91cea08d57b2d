// A sphere against the map's obstacle grid (octree/obstacle_grid.hpp): the
// cells around it read from the grid's words, each placed in key units,
// instead of a descent from the root.  The answer is the descent's
// (sphere_query.hpp) whenever it is not kUndecided: a cell within 1e-8 of
// a cell's width of the touch limit, a point extent, a sphere at the map's
// faces or wider than 60 cells leave the answer to the descent.
#pragma once

#include "geometry/aabb.hpp"
#include "octree/obstacle_grid.hpp"

namespace octoprox {

// radius: the sphere's (padding included); touching within kTouchTolerance
// counts, as everywhere.
GridAnswer sphere_on_grid(const ObstacleGrid &grid, const Vec3 &center, double radius, double resolution,
                          bool point_extents);

}  // namespace octoprox
