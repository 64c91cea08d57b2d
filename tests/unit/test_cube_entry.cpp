// The cubes where a shape's search enters the octree (octree/cube_entry.hpp):
// for random boxes on random maps, every obstacle leaf the box touches lies
// in exactly one of the cubes found, each cube touches the box and holds an
// obstacle, and there are at most eight, with or without the obstacle
// boxes' integer test.  One finder serves every box of a
// map, so its cached paths are reused across depths and octants.
#include "octree/cube_entry.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using octoprox::Aabb;
using octoprox::CellKey;
using octoprox::CubeEntries;
using octoprox::CubeEntryFinder;
using octoprox::OctreeView;
using octoprox::Vec3;

struct Leaf {
    CellKey key;
    float log_odds;
};

void collect_leaves(const OctreeView &view, OctreeView::NodeRef node, const CellKey &key, std::vector<Leaf> &out) {
    if (!view.has_children(node)) return out.push_back({key, view.log_odds(node)});
    for (int i = 0; i < 8; ++i)
        if (OctreeView::NodeRef child = view.child(node, i)) collect_leaves(view, child, key.child(i), out);
}

bool contains(const CellKey &outer, const CellKey &inner) {
    if (inner.depth < outer.depth) return false;
    for (int a = 0; a < 3; ++a)
        if (inner.key[a] < outer.key[a] || inner.key[a] >= outer.key[a] + outer.width_in_cells()) return false;
    return true;
}

// A random box: mostly shape-sized, now and then large, flat, or with faces
// exactly on cell faces (the rounding cases).
Aabb random_box(std::mt19937_64 &rng, double extent, double resolution) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Vec3 center(extent * (2 * unit(rng) - 1), extent * (2 * unit(rng) - 1), extent * (2 * unit(rng) - 1));
    const double scale = unit(rng) < 0.1 ? extent : 0.6;
    Vec3 half(scale * unit(rng), scale * unit(rng), scale * unit(rng));
    if (unit(rng) < 0.1) half.z() = 0.0;
    Aabb box = Aabb::from_center(center, half);
    if (unit(rng) < 0.2)
        for (int a = 0; a < 3; ++a)
            box.lo[a] = std::round(box.lo[a] / resolution) * resolution,
            box.hi[a] = std::max(box.lo[a], std::round(box.hi[a] / resolution) * resolution);
    return box;
}

void check_map(const octoprox::SensorOctree &tree, double extent, int boxes, uint64_t seed) {
    const OctreeView view = tree.view();
    const double res = view.resolution();
    std::vector<Leaf> leaves;
    ASSERT_NE(view.root(), nullptr);
    collect_leaves(view, view.root(), CellKey{}, leaves);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<float> threshold_draw(-1.0f, 2.0f);
    CubeEntryFinder finder(view);
    uint64_t touched_obstacles = 0, left_out_by_boxes = 0;
    for (int b = 0; b < boxes; ++b) {
        const Aabb box = random_box(rng, extent, res);
        const float threshold = threshold_draw(rng);
        // Obstacle boxes hold for thresholds at or above the map's own.
        const bool use_boxes = threshold >= view.bounds_threshold() && b % 2 == 0;
        CubeEntries entries, unfiltered;
        finder.find(box, threshold, use_boxes, entries);
        finder.find(box, threshold, false, unfiltered);
        ASSERT_LE(entries.count, unfiltered.count);
        left_out_by_boxes += unfiltered.count - entries.count;
        ASSERT_LE(entries.count, 8);
        for (int k = 0; k < entries.count; ++k) {
            const octoprox::OctreeCell &cell = entries.cells[k];
            EXPECT_GE(view.log_odds(cell.node), threshold) << "box " << b;
            const Aabb cube = octoprox::cell_box(cell.key, res);
            EXPECT_EQ(cube.lo, cell.box.lo);
            Aabb near = box;
            near.inflate(res * 1e-5);
            EXPECT_TRUE(cube.overlaps(near)) << "box " << b << ": a cube the box does not touch";
            for (int j = 0; j < k; ++j)
                EXPECT_FALSE(contains(entries.cells[j].key, cell.key) || contains(cell.key, entries.cells[j].key))
                    << "box " << b << ": nested or repeated cubes";
        }
        for (const Leaf &leaf : leaves) {
            if (leaf.log_odds < threshold || !octoprox::cell_box(leaf.key, res).overlaps(box)) continue;
            ++touched_obstacles;
            int holders = 0;
            for (int k = 0; k < entries.count; ++k) holders += contains(entries.cells[k].key, leaf.key);
            ASSERT_EQ(holders, 1) << "box " << b << ": an obstacle leaf at depth " << leaf.key.depth
                                  << " in " << holders << " cubes";
        }
    }
    EXPECT_GT(touched_obstacles, uint64_t(boxes) / 4) << "the boxes should touch obstacles often";
    EXPECT_GT(left_out_by_boxes, 0u) << "obstacle boxes should leave out some cubes beyond the boxes";
}

TEST(CubeEntry, RayCastMapsWithPrunedLeavesAndFreeSpace) {
    std::mt19937_64 rng(21);
    octoprox::OctreeParams params;
    params.resolution = 0.1103;  // not a power of two: faces are rounded
    octoprox::SensorOctree tree(params);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    for (int frame = 0; frame < 6; ++frame) {
        std::vector<double> xyz;
        for (int i = 0; i < 300; ++i) xyz.insert(xyz.end(), {coordinate(rng), coordinate(rng), coordinate(rng)});
        octoprox::InsertSettings settings;
        settings.raycast = frame % 2 == 0;
        unit::insert_xyz(tree, xyz, settings);
    }
    // A solid block: eight equal children are pruned into one leaf above.
    std::vector<double> block;
    for (double x = 0.0; x < 0.9; x += 0.05)
        for (double y = 0.0; y < 0.9; y += 0.05)
            for (double z = 0.0; z < 0.9; z += 0.05) block.insert(block.end(), {x, y, z});
    octoprox::InsertSettings endpoints;
    endpoints.raycast = false;
    for (int repeat = 0; repeat < 4; ++repeat) unit::insert_xyz(tree, block, endpoints);
    check_map(tree, 2.0, 4000, 5);
}

TEST(CubeEntry, SyntheticScene) { check_map(*unit::synthetic_octree(3), 21.0, 1500, 9); }

// The same cube asked first at a deep depth and then at a shallower one:
// the cached path must not hand back the deeper node.
TEST(CubeEntry, ShallowerAfterDeeperAtTheSameCorner) {
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    octoprox::SensorOctree tree(params);
    octoprox::InsertSettings endpoints;
    endpoints.raycast = false;
    unit::insert_xyz(tree, {0.05, 0.05, 0.05, 1.55, 1.55, 1.55}, endpoints);
    const OctreeView view = tree.view();
    CubeEntryFinder finder(view);
    CubeEntries small, large;
    finder.find(Aabb{Vec3(0.01, 0.01, 0.01), Vec3(0.02, 0.02, 0.02)}, 0.0f, false, small);
    finder.find(Aabb{Vec3(0.01, 0.01, 0.01), Vec3(1.58, 1.58, 1.58)}, 0.0f, false, large);
    ASSERT_EQ(small.count, 1);
    EXPECT_EQ(small.cells[0].key.depth, octoprox::kTreeDepth);
    int holders_of_far_cell = 0;
    const CellKey far{{uint16_t(octoprox::kKeyCenter + 15), uint16_t(octoprox::kKeyCenter + 15),
                       uint16_t(octoprox::kKeyCenter + 15)},
                      octoprox::kTreeDepth};
    for (int k = 0; k < large.count; ++k) holders_of_far_cell += contains(large.cells[k].key, far);
    EXPECT_EQ(holders_of_far_cell, 1);
}

}  // namespace
