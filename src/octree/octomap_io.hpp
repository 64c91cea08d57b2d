// Reading and writing OctoMap .bt / .ot bytes.  Input is validated before
// OctoMap parses it: OctoMap's readers trust the stream (unbounded
// recursion, reads past the end), so corrupt bytes never reach them.
#pragma once

#include "octree/sensor_octree.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace octoprox {

enum class MapFormat { kBinary, kFull };

// Parses a whole .bt/.ot file image.  Throws ApiError(CORRUPT/UNSUPPORTED).
std::unique_ptr<SensorOctree> read_map_file_bytes(const std::string &bytes, OctreeParams params);
// Parses the body only (what an octomap_msgs/Octomap message carries).
std::unique_ptr<SensorOctree> read_map_body(const std::string &body, MapFormat format,
                                            double resolution, OctreeParams params);
// The most bytes a whole .bt/.ot file can hold whose text header is at the
// start of `prefix`: the header and its node count's body (.bt: 2 bytes a
// node with children, .ot: 5 bytes a node); SIZE_MAX when the header gives
// no count.  Throws ApiError(CORRUPT) when no whole header is there.
size_t map_file_size_bound(const std::string &prefix);
// A whole .bt/.ot file image.
std::string write_map_file_bytes(const SensorOctree &tree, MapFormat format);

}  // namespace octoprox
