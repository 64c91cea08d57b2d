// reserve_update (update_reserve.cpp): after it, a frame's cell updates
// (apply_frame_cells) take every child block from the pool without growing it, whatever the
// map held before (empty, earlier frames, pruned and clamped regions), so
// an update can only run out of memory before its first cell changes; the
// count is the same on any number of threads.
#include "broadphase/morton.hpp"
#include "octree/bounded_tree.hpp"
#include "octree/frame_update.hpp"
#include "octree/update_reserve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace {

using octoprox::BoundedOcTree;

struct Frame {
    octomap::KeySet free_cells, occupied_cells;
};

// Rays from a sensor near the origin to points on a noisy wall and floor.
Frame random_frame(BoundedOcTree &tree, std::mt19937 &rng, int points) {
    std::uniform_real_distribution<float> across(-1.5f, 1.5f), noise(-0.05f, 0.05f);
    octomap::Pointcloud cloud;
    for (int i = 0; i < points; ++i) {
        if (i % 2 == 0) cloud.push_back(2.0f + noise(rng), across(rng), across(rng));
        else cloud.push_back(across(rng) + 1.0f, across(rng), -1.0f + noise(rng));
    }
    Frame frame;
    const octomap::point3d sensor(noise(rng), noise(rng), 0.2f + noise(rng));
    tree.computeUpdate(cloud, sensor, frame.free_cells, frame.occupied_cells, -1.0);
    return frame;
}

// The frame's cells as the insert hands them over: Morton order, an
// endpoint flag.
octoprox::FrameCells cells_of(const Frame &frame) {
    octoprox::FrameCells cells;
    for (const auto &key : frame.free_cells) cells.cells.push_back(octoprox::morton_encode(key[0], key[1], key[2]));
    for (const auto &key : frame.occupied_cells)
        cells.cells.push_back(octoprox::morton_encode(key[0], key[1], key[2]) | octoprox::FrameCells::kHitBit);
    std::sort(cells.cells.begin(), cells.cells.end(),
              [](uint64_t a, uint64_t b) { return octoprox::FrameCells::code(a) < octoprox::FrameCells::code(b); });
    return cells;
}

// Reserves, applies, and checks that the update never held more blocks at
// once than counted (blocks freed by a prune and taken again by a later
// expansion are the same blocks) and the pool took no new slab.
void apply_reserved(BoundedOcTree &tree, const Frame &frame) {
    const octoprox::FrameCells cells = cells_of(frame);
    const size_t needed = octoprox::child_blocks_needed(tree, cells);
    for (const size_t threads : {2, 3, 7})
        EXPECT_EQ(octoprox::child_blocks_needed(tree, cells, threads), needed) << threads << " threads";
    octoprox::reserve_update(tree, cells);
    const size_t slab_bytes = tree.child_blocks().bytes_reserved();
    const size_t in_use = tree.child_blocks().blocks_in_use();
    tree.child_blocks().reset_peak();
    octoprox::apply_frame_cells(tree, cells, {}, 0.0f);  // no point extents: occupancy alone
    EXPECT_LE(tree.child_blocks().peak_blocks_in_use() - in_use, needed);
    EXPECT_EQ(tree.child_blocks().bytes_reserved(), slab_bytes) << "the update grew the pool after its reserve";
}

TEST(UpdateReserve, FramesIntoEmptyUsedAndClampedMaps) {
    std::mt19937 rng(7);
    BoundedOcTree tree(0.05);
    for (int frame = 0; frame < 12; ++frame) apply_reserved(tree, random_frame(tree, rng, 400));
    EXPECT_GT(tree.size(), 1000u);
}

TEST(UpdateReserve, ExpandsPrunedRegions) {
    std::mt19937 rng(11);
    BoundedOcTree tree(0.1);
    // Many identical frames clamp and prune the free space; new points then
    // expand the pruned nodes again.
    const Frame same = random_frame(tree, rng, 300);
    for (int i = 0; i < 15; ++i) apply_reserved(tree, same);
    const size_t pruned_size = tree.size();
    for (int i = 0; i < 4; ++i) apply_reserved(tree, random_frame(tree, rng, 300));
    EXPECT_NE(tree.size(), pruned_size);
}

// Isolated endpoints in an empty map: no node is shared below the root's
// children and nothing prunes, so the count is exact: 16 blocks for the
// first path, then one per new node below the shared part.
TEST(UpdateReserve, CountIsExactForIsolatedCells) {
    BoundedOcTree tree(0.05);
    Frame frame;
    frame.occupied_cells.insert(tree.coordToKey(1.0, 1.0, 1.0));
    frame.occupied_cells.insert(tree.coordToKey(-1.0, 2.0, 0.5));
    frame.occupied_cells.insert(tree.coordToKey(1.0, 1.0, 1.05));  // a neighbour of the first
    const size_t needed = octoprox::child_blocks_needed(tree, cells_of(frame));
    apply_reserved(tree, frame);
    EXPECT_EQ(needed, tree.child_blocks().blocks_in_use());
    EXPECT_EQ(octoprox::child_blocks_needed(tree, cells_of(frame)), 0u);
}

}  // namespace
