// The maps of one stream at one resolution, kept across its frames as a
// robot keeps its map: every frame is inserted into the same trees.
// OctoProx: opx_octree_insert_points; OctoMap: OcTree::insertPointCloud
// (ray-cast) and a KeySet + updateNode (endpoints), the baselines of
// opx-bench-ingest, with the same parameters (OctoMap's defaults).
#pragma once

#include <cstdint>
#include <memory>

#include <octomap/OcTree.h>

#include "bench_frame.hpp"
#include "frame_stages.hpp"
#include "scene.hpp"

namespace frame_bench {

// Cells and bytes of one tree.
struct TreeMemory {
    uint64_t occupied = 0, known = 0;  // known: occupied, free and uncertain leaves
    // Heap the map holds, measured (the ingests' retained bytes, heap_meter):
    // the libraries' own counts no longer compare (OctoMap's memoryUsage
    // is a formula without the allocator's overhead; ours counts blocks).
    uint64_t bytes = 0;
    double per_occupied() const { return occupied ? double(bytes) / double(occupied) : 0.0; }
    double per_known() const { return known ? double(bytes) / double(known) : 0.0; }
};

class OpxMaps {
public:
    explicit OpxMaps(double resolution);
    // Inserts the frame (at its sensor pose) into both maps; times each.
    void ingest(const bench::Frame &frame, StageTimes &times);
    const opx_octree *raycast() const { return raycast_.get(); }
    TreeMemory raycast_memory() const;
    TreeMemory endpoints_memory() const;
    HeapBook raycast_heap, endpoints_heap;

private:
    paper_tables::OpxOctreePtr raycast_, endpoints_;
};

class OctomapMaps {
public:
    explicit OctomapMaps(double resolution);
    // As OpxMaps::ingest: the conversion of the cloud to the map frame
    // (octomap::Pointcloud) is part of each timed insert.
    void ingest(const bench::Frame &frame, StageTimes &times);
    const std::shared_ptr<octomap::OcTree> &raycast() const { return raycast_; }
    TreeMemory raycast_memory() const;
    TreeMemory endpoints_memory() const;
    HeapBook raycast_heap, endpoints_heap;

private:
    std::shared_ptr<octomap::OcTree> raycast_;
    octomap::OcTree endpoints_;
};

}  // namespace frame_bench
