// The insertion pipelines the ingest benchmark times, each on fresh trees.
#pragma once

#include "bench_frame.hpp"

#include <octomap/OcTree.h>

#include <cstdint>
#include <string>
#include <vector>

namespace bench {

enum class Pipeline {
    kOctoprox,            // opx_octree_insert_points (mode chosen by the row), 1 thread
    kOctoproxTwoThreads,  // the same with max_threads 2
    kOctomap,             // OcTree::insertPointCloud, discretize = false
    kOctomapDiscretize,   // OcTree::insertPointCloud, discretize = true
    kOctomapEndpoints,    // a KeySet of endpoint cells, then updateNode(key, true)
};
const char *pipeline_name(Pipeline pipeline);

struct RunResult {
    std::vector<double> insert_ms;  // one per repetition
    uint64_t occupied = 0, free = 0, leaves = 0;
    uint64_t memory_bytes = 0;  // the library's own count
    // Measured (heap_meter.hpp): the heap the map holds after its insert,
    // the same way for both libraries; their own counts differ (OctoMap's
    // memoryUsage is a formula without the allocator's overhead, OctoProx's
    // counts its block pool).
    uint64_t heap_bytes = 0;
    double median_ms() const;
    double bytes_per_leaf() const { return leaves ? double(memory_bytes) / double(leaves) : 0.0; }
    double heap_bytes_per_leaf() const { return leaves ? double(heap_bytes) / double(leaves) : 0.0; }
};

// raycast: OPX_INSERT_RAYCAST for kOctoprox, otherwise OPX_INSERT_ENDPOINTS.
// The OctoMap pipelines are timed from the raw float array (filtering,
// transform to the map frame in double, insert), like the library is.
// Runs the pipelines round-robin, one insert each per repetition, so that
// a change of machine load hits them all alike.
// The finite points of the frame in the map frame (the frame's sensor
// pose applied in double, rounded to float), as a user would feed OctoMap.
octomap::Pointcloud map_frame_cloud(const Frame &frame);

// OctoMap's endpoint-only insertion: a KeySet of the endpoint cells, then
// one updateNode(key, hit) per cell (the baseline of OPX_INSERT_ENDPOINTS).
void insert_endpoints(octomap::OcTree &tree, const octomap::Pointcloud &cloud);

// later: each timed insert goes into a map that already holds the frame
// once (the second frame of a stream), else into a fresh map.
std::vector<RunResult> run_interleaved(const std::vector<Pipeline> &pipelines, const Frame &frame,
                                       double resolution, bool raycast, bool later, int reps);

// What a ray-cast frame asks of a mapper: the cells its rays step through
// (OctoMap's computeRayKeys, summed over the rays) and the distinct cells
// they and the endpoints touch.
struct RayWork {
    uint64_t steps = 0, distinct_cells = 0;
};
RayWork ray_work(const Frame &frame, double resolution);

}  // namespace bench
