// The child-block store (child_blocks.cpp): whatever OctoMap does to a map
// (updates that prune and expand, deleteNode, clear, reading files), every
// child lives in its parent's block at its own slot, every empty slot reads
// as a leaf below any threshold, and the size OctoMap counts matches the
// nodes there are.  Under the sanitizer tree this also checks that no block
// leaks or is freed twice.
#include "octree/bounded_tree.hpp"
#include "octree/octomap_io.hpp"
#include "octree/octree_view.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using octoprox::OctreeView;

struct Counts {
    size_t nodes = 0;
    size_t blocks = 0;
};

// Counts the nodes below and including `node`, and their blocks, checking
// the layout on the way.
void check_blocks(const OctreeView &view, OctreeView::NodeRef node, Counts &counts) {
    ++counts.nodes;
    if (!view.has_children(node)) return;
    ++counts.blocks;
    const auto *block = static_cast<const char *>(static_cast<const octoprox::BoundedNode *>(node)->child_array());
    EXPECT_EQ(reinterpret_cast<uintptr_t>(block) % 64, 0u) << "a block is not 64-byte aligned";
    for (int i = 0; i < 8; ++i) {
        const OctreeView::NodeRef child = view.child(node, i);
        const OctreeView::NodeRef slot = view.child_or_absent(node, i);
        EXPECT_EQ(slot, block + octoprox::child_block::kSlotsOffset + octoprox::child_block::kSlotBytes * i);
        if (child == nullptr) {
            EXPECT_FALSE(view.has_children(slot));
            EXPECT_TRUE(std::isinf(view.log_odds(slot)) && view.log_odds(slot) < 0.0f) << "an empty slot's log-odds";
            continue;
        }
        EXPECT_EQ(child, slot) << "a child outside its slot";
        check_blocks(view, child, counts);
    }
}

void check_tree(const octoprox::BoundedOcTree &tree) {
    const OctreeView view(&tree, 0.0f);
    Counts counts;
    if (view.root() != nullptr) check_blocks(view, view.root(), counts);
    EXPECT_EQ(counts.nodes, tree.size());
    const octoprox::ChildBlockPool &pool = tree.child_blocks();
    EXPECT_EQ(counts.blocks, pool.blocks_in_use()) << "blocks leaked or freed twice";
    EXPECT_GE(pool.bytes_reserved(), pool.blocks_in_use() * octoprox::child_block::kBytes);
    const size_t root = tree.getRoot() == nullptr ? 0 : sizeof(octoprox::BoundedNode);
    EXPECT_EQ(tree.memoryUsage(), sizeof(octomap::BoundedTreeBase) + root + pool.bytes_reserved());
}

octomap::point3d random_point(std::mt19937_64 &rng, double extent) {
    std::uniform_real_distribution<float> coordinate(static_cast<float>(-extent), static_cast<float>(extent));
    return octomap::point3d(coordinate(rng), coordinate(rng), coordinate(rng));
}

TEST(ChildBlocks, UpdatesPruneExpandAndDelete) {
    std::mt19937_64 rng(3);
    octoprox::BoundedOcTree tree(0.1);
    const octoprox::BoundsScope scope(0.0f);
    for (int round = 0; round < 6; ++round) {
        // Rays through a small cube: cells turn free, clamp, prune, expand.
        octomap::Pointcloud cloud;
        for (int i = 0; i < 300; ++i) cloud.push_back(random_point(rng, 0.8));
        tree.insertPointCloud(cloud, random_point(rng, 0.2));
        check_tree(tree);
        // Whole cubes set one way, then pruned into one leaf.
        for (float x = 0.0f; x < 0.4f; x += 0.1f)
            for (float y = 0.0f; y < 0.4f; y += 0.1f)
                for (float z = 0.0f; z < 0.4f; z += 0.1f) tree.updateNode(octomap::point3d(x, y, z), round % 2 == 0);
        tree.prune();
        check_tree(tree);
        for (int i = 0; i < 40; ++i) tree.deleteNode(random_point(rng, 0.8));
        check_tree(tree);
        tree.expand();
        check_tree(tree);
    }
    tree.clear();
    EXPECT_EQ(tree.size(), 0u);
    EXPECT_EQ(tree.child_blocks().blocks_in_use(), 0u);
    EXPECT_EQ(tree.getRoot(), nullptr);
    tree.updateNode(octomap::point3d(0.05f, 0.05f, 0.05f), true);
    check_tree(tree);
}

TEST(ChildBlocks, ReadMapsAndTheSyntheticScene) {
    const auto scene = unit::synthetic_octree(5);
    check_tree(scene->octomap_tree());
    octoprox::OctreeParams params;
    params.resolution = 0.2;
    for (const auto format : {octoprox::MapFormat::kBinary, octoprox::MapFormat::kFull}) {
        const auto read = octoprox::read_map_file_bytes(octoprox::write_map_file_bytes(*scene, format), params);
        check_tree(read->octomap_tree());
        EXPECT_EQ(read->octomap_tree().size(), scene->octomap_tree().size());
    }
}

}  // namespace
