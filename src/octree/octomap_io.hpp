// Reading and writing OctoMap .bt / .ot bytes.  Input is validated before
// OctoMap parses it: OctoMap's readers trust the stream (unbounded
// recursion, reads past the end), so corrupt bytes never reach them.
#pragma once

#include "octree/sensor_octree.hpp"

#include <memory>
#include <string>

namespace octoprox {

enum class MapFormat { kBinary, kFull };

// Parses a whole .bt/.ot file image.  Throws ApiError(CORRUPT/UNSUPPORTED).
std::unique_ptr<SensorOctree> read_map_file_bytes(const std::string &bytes, OctreeParams params);
// Parses the body only (what an octomap_msgs/Octomap message carries).
std::unique_ptr<SensorOctree> read_map_body(const std::string &body, MapFormat format,
                                            double resolution, OctreeParams params);
// A whole .bt/.ot file image.
std::string write_map_file_bytes(const SensorOctree &tree, MapFormat format);

}  // namespace octoprox
