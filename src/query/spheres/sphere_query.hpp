// Spheres against the map, one at a time: the robot model sphere-based
// planners use.  A sphere is answered as opx_query_collide answers a link
// set holding that sphere alone (the direct engine's descent, the same
// tests and touch rule, bit for bit), without a link set to place and
// from the deepest cube holding the sphere's box: the levels above it,
// where the sphere reaches one child only, are followed by pointer alone.
#pragma once

#include "octree/sensor_octree.hpp"

namespace octoprox {

struct SphereSettings {
    float threshold_log_odds = 0.0f;  // obstacle when a cell's log-odds >= this
    bool unknown_occupied = false;
    bool point_extents = false;       // obstacle leaves are their point extents
};

// Whether the sphere (centre, radius; map frame) touches an obstacle.
// With the map's obstacle grid for settings.threshold_log_odds (may be
// null), the cells around the sphere are read from the grid, and the
// descent runs only when the grid leaves the answer open (a point extent
// near the sphere, a cell within rounding of the touch limit, a sphere at
// the map's faces or wider than 60 cells): the answer is the descent's.
// Thread-safe for a map no one changes meanwhile.
bool sphere_collides(const SensorOctree &tree, const ObstacleGrid *grid, const Vec3 &center, double radius,
                     const SphereSettings &settings);

}  // namespace octoprox
