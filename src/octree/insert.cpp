// Sensor frame insertion with OctoMap's semantics (insertPointCloud, not
// discretized, lazy evaluation off): rays make cells more free, endpoints
// more occupied, each cell is updated once per frame and an endpoint wins
// over a ray.  The map afterwards is OctoMap's, cell for cell and bit for
// bit; only the way there differs (frame_marks.hpp, frame_update.hpp).
#include "octree/sensor_octree.hpp"

#include "base/parallel.hpp"
#include "broadphase/morton.hpp"
#include "octree/bounded_tree.hpp"
#include "octree/frame_cells.hpp"
#include "octree/frame_rays.hpp"
#include "octree/frame_update.hpp"
#include "octree/ray_walk.hpp"
#include "octree/update_reserve.hpp"

#include <algorithm>
#include <atomic>
#include <memory>
#include <thread>

namespace octoprox {
namespace {

constexpr size_t kRaysPerChunk = 1024;
// Cells of the frame's box beyond the rays' ends and origin: a ray may step
// a cell past its end's cell before it stops (float rounding), and the
// walk proves a ray stays inside with a few cells of slack.
constexpr uint32_t kBoxPadding = 8;

// One thread's share of the rays: chunks taken in turn from a shared
// counter, so threads that get short rays take more of them.
struct RayWorker {
    FrameMarks marks;
    std::vector<std::vector<uint32_t>> strays;  // per segment: rays that might leave the marks' box
};

// A chunk of rays: part of one segment.
struct RayChunk {
    uint32_t segment;
    size_t begin, end;
};

std::vector<RayChunk> ray_chunks(const FrameRays &rays) {
    std::vector<RayChunk> chunks;
    for (uint32_t s = 0; s < rays.segments.size(); ++s)
        for (size_t begin = 0, size = rays.segments[s].ends.size(); begin < size; begin += kRaysPerChunk)
            chunks.push_back(RayChunk{s, begin, std::min(size, begin + kRaysPerChunk)});
    return chunks;
}

class RayCast {
public:
    RayCast(const BoundedOcTree &tree, const FrameRays &rays, const KeyBox &box)
        : rays_(rays), box_(box), walker_(tree, rays.origin, rays.origin_key), chunks_(ray_chunks(rays)) {}

    size_t chunk_count() const { return chunks_.size(); }

    void run(RayWorker &worker) {
        worker.marks.reset(box_);
        worker.strays.resize(rays_.segments.size());
        for (;;) {
            const size_t next = next_.fetch_add(1, std::memory_order_relaxed);
            if (next >= chunks_.size()) break;
            const RayChunk &chunk = chunks_[next];
            const RaySegment &segment = rays_.segments[chunk.segment];
            walker_.walk(segment.ends, segment.end_keys, chunk.begin, chunk.end, worker.marks,
                         worker.strays[chunk.segment]);
        }
    }

private:
    const FrameRays &rays_;
    const KeyBox box_;
    RayWalker walker_;
    const std::vector<RayChunk> chunks_;
    std::atomic<size_t> next_{0};
};

void mark_endpoints(const FrameRays &rays, FrameMarks &marks) {
    marks.add_endpoint_marks();
    rays.for_each_hit([&](const octomap::OcTreeKey &key) {
        const uint32_t k[3] = {key[0], key[1], key[2]};
        marks.mark_endpoint(marks.bit_of(k));
    });
}

// OctoMap's own ray for the few rays that graze the map's outer faces.
std::vector<uint64_t> stray_cells(const BoundedOcTree &tree, const FrameRays &rays,
                                  const std::vector<RayWorker> &workers) {
    std::vector<uint64_t> cells;
    octomap::KeyRay ray;
    for (const RayWorker &w : workers)
        for (size_t s = 0; s < w.strays.size(); ++s)
            for (const uint32_t index : w.strays[s]) {
                if (!tree.computeRayKeys(rays.origin, rays.segments[s].ends[index], ray)) continue;
                for (const octomap::OcTreeKey &key : ray) cells.push_back(morton_encode(key[0], key[1], key[2]));
            }
    return cells;
}

// Frames whose rays span more cells than bitmaps should cover (points
// hundreds of metres apart at a fine resolution) take OctoMap's way: a set
// of keys per ray step, then sorted.
FrameCells keyset_cells(const BoundedOcTree &tree, const FrameRays &rays, bool raycast) {
    octomap::KeySet free_cells, occupied_cells;
    rays.for_each_hit([&](const octomap::OcTreeKey &key) { occupied_cells.insert(key); });
    octomap::KeyRay ray;
    if (raycast)
        for (const RaySegment &segment : rays.segments)
            for (const octomap::point3d &end : segment.ends)
                if (tree.computeRayKeys(rays.origin, end, ray)) free_cells.insert(ray.begin(), ray.end());
    std::vector<uint64_t> cells;
    cells.reserve(free_cells.size() + occupied_cells.size());
    for (const octomap::OcTreeKey &key : occupied_cells)
        cells.push_back(morton_encode(key[0], key[1], key[2]) | FrameCells::kHitBit);
    for (const octomap::OcTreeKey &key : free_cells) cells.push_back(morton_encode(key[0], key[1], key[2]));
    return sorted_cells(std::move(cells));
}

FrameCells raycast_cells(const BoundedOcTree &tree, const FrameRays &rays, uint32_t max_threads) {
    const KeyBox box = rays.box.padded(kBoxPadding);
    if (box.volume() > FrameMarks::kMaxCells) return keyset_cells(tree, rays, true);
    RayCast cast(tree, rays, box);
    std::vector<RayWorker> workers(task_count(max_threads, cast.chunk_count()));
    run_tasks(workers.size(), [&](size_t i) { cast.run(workers[i]); });
    FrameMarks &marks = workers[0].marks;
    for (size_t i = 1; i < workers.size(); ++i) marks.merge_crossed(workers[i].marks);
    mark_endpoints(rays, marks);
    return collect_cells(marks, stray_cells(tree, rays, workers), max_threads);
}

FrameCells endpoint_cells(const BoundedOcTree &tree, const FrameRays &rays) {
    if (rays.box.volume() > FrameMarks::kMaxCells) return keyset_cells(tree, rays, false);
    FrameMarks marks;
    marks.reset(rays.box);
    mark_endpoints(rays, marks);
    return collect_cells(marks, {});
}

}  // namespace

InsertCounts SensorOctree::insert(const PointSource &points, const InsertSettings &settings) {
    InsertCounts counts;
    const FrameRays rays =
        prepare_rays(*this, points, settings, task_count(settings.max_threads, points.count / 4096 + 1), counts);
    FrameCells cells =
        settings.raycast ? raycast_cells(*tree_, rays, settings.max_threads) : endpoint_cells(*tree_, rays);
    if (settings.clear_cells != nullptr) add_clear_cells(cells, *settings.clear_cells);
    if (settings.bounds != nullptr) clip_cells(cells, *settings.bounds);
    // Everything that may allocate happens above or here: the cell updates
    // below take their nodes from reserved blocks, so a frame goes into the
    // map whole or, out of memory, not at all.  (An empty map's root is made
    // by the update, before any cell changes.)
    const size_t update_threads = frame_update_threads(cells, settings.max_threads);
    reserve_update(*tree_, cells, update_threads);
    ++generation_;
    {
        const BoundsScope scope(occupied_log_odds_);  // keeps the inner obstacle boxes
        apply_frame_cells(*tree_, cells, rays.hit_extents, occupied_log_odds_, update_threads);
    }
    tree_->child_blocks().release_spares();
    grow_known_bounds(cells.box);
    counts.cells_missed = cells.misses;
    counts.cells_hit = cells.hits;
    counts.cells_cleared = cells.cleared;
    return counts;
}

}  // namespace octoprox
