#include "bench_pipelines.hpp"

#include "heap_meter.hpp"

#include <octoprox/octoprox.h>

#include <octomap/OcTree.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace bench {
namespace {

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void check(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

// One OctoProx insert on a fresh tree; the stats of the last one are kept.
double insert_octoprox(const Frame &frame, double resolution, bool raycast, uint32_t threads, bool later,
                       RunResult *keep_stats) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    opx_octree *tree = nullptr;
    check(opx_octree_create(&options, &tree), "opx_octree_create");
    const uint64_t heap_before = heap_live_bytes();  // the empty map's buffers (OctoMap's key ray) not counted
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = raycast ? OPX_INSERT_RAYCAST : OPX_INSERT_ENDPOINTS;
    insert.max_threads = threads;
    std::memcpy(insert.sensor_pose.position, frame.position, sizeof frame.position);
    std::memcpy(insert.sensor_pose.orientation, frame.quaternion_xyzw, sizeof frame.quaternion_xyzw);
    if (later)
        check(opx_octree_insert_points(tree, frame.xyz.data(), frame.count, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
              "opx_octree_insert_points");
    const Clock::time_point start = Clock::now();
    check(opx_octree_insert_points(tree, frame.xyz.data(), frame.count, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
          "opx_octree_insert_points");
    const double ms = elapsed_ms(start);
    if (keep_stats != nullptr) {
        opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
        check(opx_octree_get_stats(tree, &stats), "opx_octree_get_stats");
        keep_stats->occupied = stats.leaves_occupied;
        keep_stats->free = stats.leaves_free;
        keep_stats->leaves = stats.leaves_occupied + stats.leaves_uncertain + stats.leaves_free;
        keep_stats->memory_bytes = stats.memory_bytes;
        keep_stats->heap_bytes = heap_live_bytes() - heap_before;
    }
    opx_octree_destroy(tree);
    return ms;
}

void keep_octomap_stats(const octomap::OcTree &tree, RunResult *out) {
    out->occupied = out->free = 0;
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it)
        ++(tree.isNodeOccupied(*it) ? out->occupied : out->free);
    out->leaves = out->occupied + out->free;
    out->memory_bytes = tree.memoryUsage();
}

void octomap_frame(Pipeline pipeline, const Frame &frame, octomap::OcTree &tree) {
    const octomap::Pointcloud cloud = map_frame_cloud(frame);
    const octomap::point3d origin(float(frame.position[0]), float(frame.position[1]), float(frame.position[2]));
    if (pipeline == Pipeline::kOctomapEndpoints)
        insert_endpoints(tree, cloud);
    else
        tree.insertPointCloud(cloud, origin, -1.0, false, pipeline == Pipeline::kOctomapDiscretize);
}  // the cloud freed inside the timing, as our insert frees its own copies

double insert_octomap(Pipeline pipeline, const Frame &frame, double resolution, bool later, RunResult *keep_stats) {
    octomap::OcTree tree(resolution);
    const uint64_t heap_before = heap_live_bytes();  // as for OctoProx: the empty tree's key ray not counted
    if (later) octomap_frame(pipeline, frame, tree);
    const Clock::time_point start = Clock::now();
    octomap_frame(pipeline, frame, tree);
    const double ms = elapsed_ms(start);
    if (keep_stats != nullptr) {
        keep_stats->heap_bytes = heap_live_bytes() - heap_before;
        keep_octomap_stats(tree, keep_stats);
    }
    return ms;
}

}  // namespace

// Rotated in double (a rotation matrix from the unit quaternion).
octomap::Pointcloud map_frame_cloud(const Frame &frame) {
    const double *q = frame.quaternion_xyzw;
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    const double x = q[0] / n, y = q[1] / n, z = q[2] / n, w = q[3] / n;
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    octomap::Pointcloud cloud;
    cloud.reserve(frame.finite_count);
    for (size_t i = 0; i < frame.count; ++i) {
        const float *p = &frame.xyz[3 * i];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
        float m[3];
        for (int row = 0; row < 3; ++row)
            m[row] = static_cast<float>(r[row][0] * p[0] + r[row][1] * p[1] + r[row][2] * p[2] + frame.position[row]);
        cloud.push_back(m[0], m[1], m[2]);
    }
    return cloud;
}

void insert_endpoints(octomap::OcTree &tree, const octomap::Pointcloud &cloud) {
    octomap::KeySet cells;
    for (const octomap::point3d &p : cloud) {
        octomap::OcTreeKey key;
        if (tree.coordToKeyChecked(p, key)) cells.insert(key);
    }
    for (const octomap::OcTreeKey &key : cells) tree.updateNode(key, true, false);
}

const char *pipeline_name(Pipeline pipeline) {
    switch (pipeline) {
    case Pipeline::kOctoprox: return "octoprox";
    case Pipeline::kOctoproxTwoThreads: return "octoprox 2 threads";
    case Pipeline::kOctomap: return "octomap insertPointCloud";
    case Pipeline::kOctomapDiscretize: return "octomap insertPointCloud discretize";
    case Pipeline::kOctomapEndpoints: return "octomap KeySet + updateNode";
    }
    return "?";
}

double RunResult::median_ms() const {
    std::vector<double> sorted = insert_ms;
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    if (n == 0) return 0.0;
    return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

std::vector<RunResult> run_interleaved(const std::vector<Pipeline> &pipelines, const Frame &frame,
                                       double resolution, bool raycast, bool later, int reps) {
    std::vector<RunResult> results(pipelines.size());
    for (int rep = 0; rep < reps; ++rep) {
        for (size_t i = 0; i < pipelines.size(); ++i) {
            RunResult *keep = rep + 1 == reps ? &results[i] : nullptr;
            const Pipeline p = pipelines[i];
            const bool ours = p == Pipeline::kOctoprox || p == Pipeline::kOctoproxTwoThreads;
            const double ms = ours ? insert_octoprox(frame, resolution, raycast,
                                                     p == Pipeline::kOctoproxTwoThreads ? 2 : 1, later, keep)
                                   : insert_octomap(p, frame, resolution, later, keep);
            results[i].insert_ms.push_back(ms);
        }
    }
    return results;
}

RayWork ray_work(const Frame &frame, double resolution) {
    octomap::OcTree tree(resolution);
    const octomap::Pointcloud cloud = map_frame_cloud(frame);
    const octomap::point3d origin(float(frame.position[0]), float(frame.position[1]), float(frame.position[2]));
    RayWork work;
    octomap::KeyRay ray;
    for (const octomap::point3d &p : cloud)
        if (tree.computeRayKeys(origin, p, ray)) work.steps += ray.size();
    octomap::KeySet free_cells, occupied_cells;
    tree.computeUpdate(cloud, origin, free_cells, occupied_cells, -1.0);
    work.distinct_cells = free_cells.size() + occupied_cells.size();
    return work;
}

}  // namespace bench
