// A sensor frame's points as rays in the map frame, filtered and counted
// the way OctoMap's insertPointCloud treats them: float coordinates, a
// point beyond max_range cut to a ray of max_range that only frees cells,
// a ray whose end lies outside the map dropped.
#pragma once

#include "broadphase/morton.hpp"
#include "octree/frame_marks.hpp"
#include "octree/point_extent.hpp"
#include "octree/sensor_octree.hpp"

#include <octomap/OcTreeKey.h>
#include <octomap/octomap_types.h>

#include <vector>

namespace octoprox {

// The rays of one run of the frame's points (one per thread that
// prepared them), in the points' order: each ray's end and its key.  Rays
// cut at max_range are among them; the occupied end cells are the hit
// extents' (FrameRays::for_each_hit).
struct RaySegment {
    std::vector<octomap::point3d> ends;
    std::vector<octomap::OcTreeKey> end_keys;
};

struct FrameRays {
    octomap::point3d origin;
    octomap::OcTreeKey origin_key;  // meaningful in ray-cast mode (the origin lies in the map)
    // The segments stay apart: joining them would copy every ray once
    // more, on one thread, into memory touched for the first time.
    std::vector<RaySegment> segments;
    // The extent of the points in each occupied end cell, ascending by
    // Morton code, one entry a cell (point_extent.hpp).
    std::vector<CellExtent> hit_extents;
    KeyBox box;  // keys of the origin and every end

    // Calls hit(key) once for every occupied end cell (an end of a ray not
    // cut at max_range), from the hit extents' codes: a few thousand cells
    // where the rays number hundreds of thousands.
    template <class Hit>
    void for_each_hit(Hit &&hit) const {
        for (const CellExtent &cell : hit_extents) {
            uint32_t x, y, z;
            morton_decode(cell.code, x, y, z);
            hit(octomap::OcTreeKey(static_cast<octomap::key_type>(x), static_cast<octomap::key_type>(y),
                                   static_cast<octomap::key_type>(z)));
        }
    }
};

// Throws ApiError(INVALID_ARGUMENT) when the sensor lies outside the map.
// Uses up to `threads` threads (the caller's included).
FrameRays prepare_rays(const SensorOctree &tree, const PointSource &points, const InsertSettings &settings,
                       size_t threads, InsertCounts &counts);

}  // namespace octoprox
