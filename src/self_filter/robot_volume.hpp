// The finest cells of a map lying entirely inside the robot's unpadded
// solids (self-filtering's clear_robot_volume): a cell counts when its
// closed cube lies inside one solid (all eight corners inside a convex
// solid; for a closed mesh, all eight corners inside and no triangle
// touching the cube).
#pragma once

#include "self_filter/padded_robot.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

// Morton codes of the cells' keys (OctoMap's: key = floor(coordinate /
// resolution) + 32768 per axis), ascending, each once.
std::vector<uint64_t> robot_volume_cells(const PaddedRobot &robot, double resolution);

}  // namespace octoprox
