// Checks shared by the query requests (collision, distance, path).
#pragma once

#include "octree/sensor_octree.hpp"
#include "query/distance_types.hpp"

#include <octoprox/query.h>

#include <cstdint>

namespace octoprox::capi {

// OPX_UNKNOWN_FREE or OPX_UNKNOWN_OCCUPIED; true for occupied.
bool read_unknown_policy(int32_t policy, const char *argument);
// OPX_OBSTACLE_CELLS or OPX_OBSTACLE_POINT_EXTENTS (true), checked.
bool read_obstacle_geometry(int32_t geometry, const char *argument);
// 0 (the octree's occupied threshold) or a probability in (0, 1), as the
// float log-odds the engines compare with.
float read_threshold_log_odds(double threshold, const SensorOctree &tree, const char *argument);
// The fields of a distance request that do not depend on the map: abs_err,
// rel_err, cutoff (0: none) and signed_distance, checked.
DistanceSettings read_distance_bounds(const opx_distance_request &request);

}  // namespace octoprox::capi
