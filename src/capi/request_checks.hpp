// Checks shared by the query requests (collision, distance, path).
#pragma once

#include "octree/sensor_octree.hpp"

#include <cstdint>

namespace octoprox::capi {

// OPX_UNKNOWN_FREE or OPX_UNKNOWN_OCCUPIED; true for occupied.
bool read_unknown_policy(int32_t policy, const char *argument);
// 0 (the octree's occupied threshold) or a probability in (0, 1), as the
// float log-odds the engines compare with.
float read_threshold_log_odds(double threshold, const SensorOctree &tree, const char *argument);

}  // namespace octoprox::capi
