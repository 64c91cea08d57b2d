// OctoProx map files (.opx): what .bt and .ot files cannot hold, the point
// extents of the occupied leaves (point_extent.hpp), beside the map itself.
//
// Layout: the line "# OctoProx map 1", the line "ot_bytes N", N bytes of a
// complete OctoMap .ot file (every node's log-odds), the line "extents M",
// then M little-endian uint32: every leaf's packed extent (0: none), in
// depth-first order with children by index.  OctoMap tools read the .ot
// part when it is cut out.
#pragma once

#include "octree/sensor_octree.hpp"

#include <memory>
#include <string>

namespace octoprox {

bool is_octoprox_map(const std::string &bytes);
// Throws ApiError(CORRUPT) on anything but a whole, consistent file.
std::unique_ptr<SensorOctree> read_octoprox_map_bytes(const std::string &bytes, OctreeParams params);
// The most bytes a whole .opx file starting with `prefix` can hold, from
// its "ot_bytes" line.  Throws ApiError(CORRUPT) when that line is not there.
size_t octoprox_map_size_bound(const std::string &prefix);
std::string write_octoprox_map_bytes(const SensorOctree &tree);

}  // namespace octoprox
