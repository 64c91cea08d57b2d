// The parallel frame update (apply_frame_cells_split, frame_update.cpp)
// gives the single pass's map node for node: the same nodes at every
// depth, log-odds, point extents and obstacle boxes, the same node count,
// whatever the thread count and the depth the frame is split at, on empty,
// used, clamped and pruned maps; and it takes its blocks within the
// reserve.
#include "broadphase/morton.hpp"
#include "octree/bounded_tree.hpp"
#include "octree/frame_update.hpp"
#include "octree/update_reserve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

namespace {

using octoprox::BoundedOcTree;
using octoprox::CellExtent;
using octoprox::FrameCells;

constexpr float kOccupied = 0.0f;  // log-odds threshold of the obstacle boxes

struct Frame {
    FrameCells cells;
    std::vector<CellExtent> extents;  // one per hit cell, ascending
};

// Rays from a sensor near the origin to a noisy wall and floor (OctoMap's
// own computeUpdate gives the cells), every hit cell with a random extent.
Frame random_frame(const BoundedOcTree &tree, std::mt19937 &rng, int points, float spread) {
    std::uniform_real_distribution<float> across(-spread, spread), noise(-0.05f, 0.05f);
    std::uniform_int_distribution<int> slot(0, 31);
    octomap::Pointcloud cloud;
    for (int i = 0; i < points; ++i) {
        if (i % 2 == 0) cloud.push_back(2.0f + noise(rng), across(rng), across(rng));
        else cloud.push_back(across(rng) + 1.0f, across(rng), -1.0f + noise(rng));
    }
    octomap::KeySet free_cells, occupied_cells;
    const octomap::point3d sensor(noise(rng), noise(rng), 0.2f + noise(rng));
    const_cast<BoundedOcTree &>(tree).computeUpdate(cloud, sensor, free_cells, occupied_cells, -1.0);
    Frame frame;
    auto add = [&](const octomap::OcTreeKey &key, bool hit) {
        const uint32_t k[3] = {key[0], key[1], key[2]};
        const uint64_t code = octoprox::morton_encode(k[0], k[1], k[2]);
        frame.cells.cells.push_back(hit ? code | FrameCells::kHitBit : code);
        frame.cells.box.grow(k);
        if (!hit) return;
        int lo[3], hi[3];
        for (int axis = 0; axis < 3; ++axis) {
            const int a = slot(rng), b = slot(rng);
            lo[axis] = std::min(a, b), hi[axis] = std::max(a, b);
        }
        frame.extents.push_back(CellExtent{code, octoprox::extent::pack(lo, hi)});
    };
    for (const auto &key : occupied_cells) add(key, true);
    for (const auto &key : free_cells)
        if (occupied_cells.count(key) == 0) add(key, false);
    auto by_code = [](uint64_t a, uint64_t b) { return FrameCells::code(a) < FrameCells::code(b); };
    std::sort(frame.cells.cells.begin(), frame.cells.cells.end(), by_code);
    std::sort(frame.extents.begin(), frame.extents.end(),
              [](const CellExtent &a, const CellExtent &b) { return a.code < b.code; });
    return frame;
}

// Every node, depth first in child order, as (depth, child index path
// step, log-odds bits, packed bounds or extent, has children).
std::vector<uint64_t> nodes_of(const BoundedOcTree &tree) {
    std::vector<uint64_t> out;
    struct Walk {
        const BoundedOcTree &tree;
        std::vector<uint64_t> &out;
        void node(const octoprox::BoundedNode *n, unsigned depth, unsigned index) {
            const float value = n->getLogOdds();
            uint32_t bits;
            std::memcpy(&bits, &value, sizeof bits);
            const bool inner = tree.nodeHasChildren(n);
            out.push_back((uint64_t{depth} << 40) | (uint64_t{index} << 36) | (uint64_t{inner} << 35));
            out.push_back((uint64_t{bits} << 32) | n->packed_bounds());
            if (!inner) return;
            for (unsigned i = 0; i < 8; ++i)
                if (tree.nodeChildExists(n, i)) node(tree.getNodeChild(n, i), depth + 1, i);
        }
    };
    if (tree.getRoot() != nullptr) Walk{tree, out}.node(tree.getRoot(), 0, 0);
    return out;
}

void apply(BoundedOcTree &tree, const Frame &frame, size_t threads, int split_depth) {
    octoprox::reserve_update(tree, frame.cells, threads);
    const size_t slab_bytes = tree.child_blocks().bytes_reserved();
    const octoprox::BoundsScope scope(kOccupied);
    if (threads == 1 && split_depth == 0) octoprox::apply_frame_cells(tree, frame.cells, frame.extents, kOccupied);
    else octoprox::apply_frame_cells_split(tree, frame.cells, frame.extents, kOccupied, threads, split_depth);
    EXPECT_EQ(tree.child_blocks().bytes_reserved(), slab_bytes) << "the update grew the pool after its reserve";
}

// A clamped free cube of 32 cells across around the map's centre, pruned
// into 8 leaves 3 levels above the finest.
void clamped_free_cube(BoundedOcTree &tree) {
    const octoprox::BoundsScope scope(kOccupied);
    for (int x = -16; x < 16; ++x)
        for (int y = -16; y < 16; ++y)
            for (int z = -16; z < 16; ++z) {
                const octomap::OcTreeKey key(32768 + x, 32768 + y, 32768 + z);
                for (int i = 0; i < 12; ++i) tree.updateNode(key, false);
            }
    tree.prune();
}

// The same frames into a map updated in one pass and into maps split at
// every depth on 1 to 3 threads: the same nodes after every frame.
void check_frames(const std::vector<Frame> &frames, double resolution, bool start_clamped = false) {
    BoundedOcTree single(resolution);
    if (start_clamped) clamped_free_cube(single);
    std::vector<std::vector<uint64_t>> expected;
    std::vector<size_t> sizes;
    for (const Frame &frame : frames) {
        apply(single, frame, 1, 0);
        expected.push_back(nodes_of(single));
        sizes.push_back(single.size());
    }
    for (const size_t threads : {1, 2, 3}) {
        for (int split_depth = 1; split_depth < 16; ++split_depth) {
            BoundedOcTree split(resolution);
            if (start_clamped) clamped_free_cube(split);
            for (size_t i = 0; i < frames.size(); ++i) {
                apply(split, frames[i], threads, split_depth);
                ASSERT_EQ(nodes_of(split), expected[i])
                    << threads << " threads, split at depth " << split_depth << ", frame " << i;
                ASSERT_EQ(split.size(), sizes[i]);
            }
            EXPECT_EQ(split.child_blocks().blocks_in_use(), single.child_blocks().blocks_in_use());
        }
    }
}

// `count` random frames (random_frame) at `resolution`.
std::vector<Frame> random_frames(unsigned seed, double resolution, int count, int points, float spread) {
    std::mt19937 rng(seed);
    const BoundedOcTree probe(resolution);
    std::vector<Frame> frames;
    for (int i = 0; i < count; ++i) frames.push_back(random_frame(probe, rng, points, spread));
    return frames;
}

TEST(FrameUpdateSplit, FramesIntoEmptyAndUsedMaps) { check_frames(random_frames(3, 0.05, 4, 300, 1.5f), 0.05); }

// Repeated frames clamp and prune the free space (pruned leaves above the
// split keep cells they clamp, and open for the others); new points then
// expand pruned nodes again.
TEST(FrameUpdateSplit, ClampedAndPrunedMaps) {
    const std::vector<Frame> fresh = random_frames(9, 0.1, 4, 200, 1.0f);
    std::vector<Frame> frames(12, fresh[0]);
    frames.insert(frames.end(), fresh.begin() + 1, fresh.end());
    check_frames(frames, 0.1);
}

// Frames into a pruned clamped free region: its leaves above the split
// keep the free cells they clamp and open for the endpoints.
TEST(FrameUpdateSplit, PrunedLeavesAboveTheSplit) { check_frames(random_frames(15, 0.1, 3, 200, 1.0f), 0.1, true); }

// A frame spread over the map's centre, where the root's children part:
// subtrees on both sides of every axis.
TEST(FrameUpdateSplit, FrameAcrossTheMapCentre) { check_frames(random_frames(21, 0.2, 1, 400, 3.0f), 0.2); }

}  // namespace
