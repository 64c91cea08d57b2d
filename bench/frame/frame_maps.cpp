#include "frame_maps.hpp"

#include "bench_pipelines.hpp"
#include "timing.hpp"

namespace frame_bench {
namespace {

using paper_tables::check_opx;
using paper_tables::time_once_ms;

paper_tables::OpxOctreePtr make_tree(double resolution) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    opx_octree *raw = nullptr;
    check_opx(opx_octree_create(&options, &raw), "opx_octree_create");
    return paper_tables::OpxOctreePtr(raw);
}

void insert(opx_octree *tree, const bench::Frame &frame, int32_t mode) {
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = mode;
    insert.max_threads = 0;  // every core: a workstation's setting (FCL and OctoMap have one thread)
    for (int i = 0; i < 3; ++i) insert.sensor_pose.position[i] = frame.position[i];
    for (int i = 0; i < 4; ++i) insert.sensor_pose.orientation[i] = frame.quaternion_xyzw[i];
    check_opx(opx_octree_insert_points(tree, frame.xyz.data(), frame.count, 0, OPX_SCALAR_FLOAT32, &insert, nullptr),
              "opx_octree_insert_points");
}

// Times `work` into `ms` and books its heap.
template <class Work>
void timed(Work &&work, double &ms, HeapBook &book) {
    book.add(measure_heap([&] { ms = time_once_ms(work); }));
}

uint64_t held_bytes(const HeapBook &book) { return book.held > 0 ? static_cast<uint64_t>(book.held) : 0; }

TreeMemory opx_memory(const opx_octree *tree, const HeapBook &book) {
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(tree, &stats), "opx_octree_get_stats");
    return {stats.leaves_occupied, stats.leaves_occupied + stats.leaves_free + stats.leaves_uncertain,
            held_bytes(book)};
}

TreeMemory octomap_memory(const octomap::OcTree &tree, const HeapBook &book) {
    TreeMemory memory;
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
        ++memory.known;
        memory.occupied += tree.isNodeOccupied(*it);
    }
    memory.bytes = held_bytes(book);
    return memory;
}

}  // namespace

OpxMaps::OpxMaps(double resolution) : raycast_(make_tree(resolution)), endpoints_(make_tree(resolution)) {}

void OpxMaps::ingest(const bench::Frame &frame, StageTimes &times) {
    timed([&] { insert(raycast_.get(), frame, OPX_INSERT_RAYCAST); }, times[kIngestRaycast], raycast_heap);
    timed([&] { insert(endpoints_.get(), frame, OPX_INSERT_ENDPOINTS); }, times[kIngestEndpoints], endpoints_heap);
}

TreeMemory OpxMaps::raycast_memory() const { return opx_memory(raycast_.get(), raycast_heap); }
TreeMemory OpxMaps::endpoints_memory() const { return opx_memory(endpoints_.get(), endpoints_heap); }

OctomapMaps::OctomapMaps(double resolution)
    : raycast_(std::make_shared<octomap::OcTree>(resolution)), endpoints_(resolution) {}

void OctomapMaps::ingest(const bench::Frame &frame, StageTimes &times) {
    const octomap::point3d origin(float(frame.position[0]), float(frame.position[1]), float(frame.position[2]));
    timed([&] { raycast_->insertPointCloud(bench::map_frame_cloud(frame), origin, -1.0, false, false); },
          times[kIngestRaycast], raycast_heap);
    timed([&] { bench::insert_endpoints(endpoints_, bench::map_frame_cloud(frame)); }, times[kIngestEndpoints],
          endpoints_heap);
}

TreeMemory OctomapMaps::raycast_memory() const { return octomap_memory(*raycast_, raycast_heap); }
TreeMemory OctomapMaps::endpoints_memory() const { return octomap_memory(endpoints_, endpoints_heap); }

}  // namespace frame_bench
