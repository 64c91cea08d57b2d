// A sensor frame's points as rays in the map frame, filtered and counted
// the way OctoMap's insertPointCloud treats them: float coordinates, a
// point beyond max_range cut to a ray of max_range that only frees cells,
// a ray whose end lies outside the map dropped.
#pragma once

#include "octree/frame_marks.hpp"
#include "octree/point_extent.hpp"
#include "octree/sensor_octree.hpp"

#include <octomap/OcTreeKey.h>
#include <octomap/octomap_types.h>

#include <vector>

namespace octoprox {

struct FrameRays {
    octomap::point3d origin;
    octomap::OcTreeKey origin_key;  // meaningful in ray-cast mode (the origin lies in the map)
    // Every ray's end and its key (in no particular order), and the keys
    // of the ends that are occupied cells (rays cut at max_range have none).
    std::vector<octomap::point3d> ends;
    std::vector<octomap::OcTreeKey> end_keys;
    std::vector<octomap::OcTreeKey> hit_keys;
    // The extent of the points in each occupied end cell, ascending by
    // Morton code, one entry a cell (point_extent.hpp).
    std::vector<CellExtent> hit_extents;
    KeyBox box;                               // keys of the origin and every end
};

// Throws ApiError(INVALID_ARGUMENT) when the sensor lies outside the map.
// Uses up to `threads` threads (the caller's included).
FrameRays prepare_rays(const SensorOctree &tree, const PointSource &points, const InsertSettings &settings,
                       size_t threads, InsertCounts &counts);

}  // namespace octoprox
