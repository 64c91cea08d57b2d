// The obstacle boxes kept in the map's inner nodes (bounded_tree.hpp):
// after any sequence of changes every inner node holding an obstacle
// carries a valid box, and that box is exactly the slot-rounded bounds of
// the obstacle leaves below it (computed here from the leaves' keys).
#include "octree/bounded_tree.hpp"
#include "octree/octomap_io.hpp"
#include "octree/octree_cell.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace {

using octoprox::CellKey;
using octoprox::OctreeView;

struct KeyBounds {
    int64_t lo[3] = {INT64_MAX, INT64_MAX, INT64_MAX};
    int64_t hi[3] = {INT64_MIN, INT64_MIN, INT64_MIN};  // exclusive
    bool empty() const { return lo[0] == INT64_MAX; }
    void grow(const KeyBounds &b) {
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], b.lo[a]), hi[a] = std::max(hi[a], b.hi[a]);
    }
};

struct Checker {
    OctreeView view;
    float threshold;
    uint64_t inner_checked = 0;

    // Returns the key bounds of the obstacle leaves below `node`, checking
    // every inner node's packed box on the way.
    KeyBounds check(OctreeView::NodeRef node, const CellKey &cell) {
        KeyBounds leaves;
        if (!view.has_children(node)) {
            if (view.log_odds(node) >= threshold)
                for (int a = 0; a < 3; ++a) leaves.lo[a] = cell.key[a], leaves.hi[a] = cell.key[a] + cell.width_in_cells();
            return leaves;
        }
        int children = 0;
        for (int i = 0; i < 8; ++i)
            if (OctreeView::NodeRef child = view.child(node, i)) leaves.grow(check(child, cell.child(i))), ++children;
        // has_children reads only the child array: it must never be empty.
        EXPECT_GT(children, 0) << "a child array without children at depth " << cell.depth;
        EXPECT_EQ(leaves.empty(), !(view.log_odds(node) >= threshold)) << "inner max log-odds disagrees";
        if (!leaves.empty()) expect_packed(view.packed_obstacle_bounds(node), cell, leaves);
        return leaves;
    }

    void expect_packed(uint32_t packed, const CellKey &cell, const KeyBounds &leaves) {
        ++inner_checked;
        ASSERT_NE(packed & octoprox::bounds::kValid, 0u) << "depth " << cell.depth;
        const int64_t width = cell.width_in_cells();
        for (int a = 0; a < 3; ++a) {
            // Slots of width/32 cells: the lowest slot touched, and the
            // highest (the exclusive end rounded up, minus one).
            const int64_t lo_slot = ((leaves.lo[a] - cell.key[a]) * 32) / width;
            const int64_t hi_slot = ((leaves.hi[a] - cell.key[a]) * 32 + width - 1) / width - 1;
            ASSERT_EQ(octoprox::bounds::lo(packed, a), lo_slot) << "axis " << a << " depth " << cell.depth;
            ASSERT_EQ(octoprox::bounds::hi(packed, a), hi_slot) << "axis " << a << " depth " << cell.depth;
        }
        // The box the engines use contains every obstacle leaf's exact box.
        const double res = view.resolution();
        const octoprox::OctreeCell whole{nullptr, cell, octoprox::cell_box(cell, res)};
        const octoprox::Aabb box = octoprox::obstacle_box(whole, packed, octoprox::obstacle_box_pad(res));
        for (int a = 0; a < 3; ++a) {
            EXPECT_LE(box.lo[a], (leaves.lo[a] - octoprox::kKeyCenter) * res);
            EXPECT_GE(box.hi[a], (leaves.hi[a] - octoprox::kKeyCenter) * res);
        }
    }
};

uint64_t check_tree(const octoprox::SensorOctree &tree) {
    Checker checker{tree.view(), tree.view().bounds_threshold()};
    if (OctreeView::NodeRef root = checker.view.root()) checker.check(root, CellKey{});
    return checker.inner_checked;
}

// A frame of random points in a small room, ray cast from `origin`.
void insert_frame(octoprox::SensorOctree &tree, std::mt19937_64 &rng, bool raycast, double extent) {
    std::uniform_real_distribution<double> coordinate(-extent, extent);
    std::vector<double> xyz;
    for (int i = 0; i < 400; ++i) xyz.insert(xyz.end(), {coordinate(rng), coordinate(rng), coordinate(rng)});
    octoprox::InsertSettings settings;
    settings.raycast = raycast;
    settings.sensor_pose.translation = octoprox::Vec3(coordinate(rng), coordinate(rng), coordinate(rng)) * 0.2;
    unit::insert_xyz(tree, xyz, settings);
}

TEST(ObstacleBounds, RayCastFramesKeepExactBoxes) {
    std::mt19937_64 rng(7);
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    octoprox::SensorOctree tree(params);
    for (int frame = 0; frame < 30; ++frame) {
        // A small extent makes rays cross cells many times: cells turn
        // free again, clamp, prune and expand.
        insert_frame(tree, rng, frame % 3 != 2, frame < 15 ? 1.0 : 0.4);
        ASSERT_GT(check_tree(tree), 0u) << "frame " << frame;
    }
}

TEST(ObstacleBounds, HigherThresholdMapsAndSyntheticScene) {
    std::mt19937_64 rng(11);
    octoprox::OctreeParams params;
    params.resolution = 0.05;
    params.occupied_threshold = 0.8;
    octoprox::SensorOctree tree(params);
    for (int frame = 0; frame < 10; ++frame) insert_frame(tree, rng, true, 0.5);
    EXPECT_GT(check_tree(tree), 0u);
    EXPECT_GT(check_tree(*unit::synthetic_octree(3)), 1000u);
}

TEST(ObstacleBounds, ReadMapsGetBoxes) {
    std::mt19937_64 rng(5);
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    octoprox::SensorOctree tree(params);
    for (int frame = 0; frame < 8; ++frame) insert_frame(tree, rng, true, 1.0);
    for (const auto format : {octoprox::MapFormat::kBinary, octoprox::MapFormat::kFull}) {
        const auto read = octoprox::read_map_file_bytes(octoprox::write_map_file_bytes(tree, format), params);
        EXPECT_GT(check_tree(*read), 0u);
    }
    const std::string geb079 = unit::data_dir() + "/maps/geb079.bt";
    if (!unit::file_exists(geb079)) UNIT_SKIP_WITHOUT_DATA("no shared data at " + geb079);
    EXPECT_GT(check_tree(*unit::read_octree(geb079)), 1000u);
}

TEST(ObstacleBounds, ChangesOutsideAScopeMarkNodesUnknown) {
    octoprox::BoundedOcTree tree(0.1);
    tree.updateNode(octomap::point3d(0.05f, 0.05f, 0.05f), true);
    const octoprox::BoundedNode *root = tree.getRoot();
    ASSERT_NE(root, nullptr);
    EXPECT_EQ(root->packed_bounds(), 0u);
    {
        const octoprox::BoundsScope scope(0.0f);
        tree.updateNode(octomap::point3d(0.05f, 0.05f, 0.05f), true);
    }
    EXPECT_NE(root->packed_bounds() & octoprox::bounds::kValid, 0u);
}

}  // namespace
