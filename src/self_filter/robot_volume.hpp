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

// The most cell corners the solids' boxes may span together (each corner
// is tested once): a robot many metres wide at a millimetre resolution
// would take minutes and gigabytes.
constexpr double kMaxVolumeCorners = double(uint64_t{1} << 26);

// Morton codes of the cells' keys (OctoMap's: key = floor(coordinate /
// resolution) + 32768 per axis), ascending, each once.  Throws
// ApiError(INVALID_ARGUMENT) naming options.clear_robot_volume when the
// solids' boxes span more than kMaxVolumeCorners corners.
std::vector<uint64_t> robot_volume_cells(const PaddedRobot &robot, double resolution);

}  // namespace octoprox
