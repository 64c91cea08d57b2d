// Clearing, decay, cropping and bounded inserts on random maps, against a
// brute force over every finest cell: each cell's log-odds and point
// extent before, what the edit's rule says of that cell, and the map after.
// The maps after are also checked whole: node counts, block counts, inner
// nodes holding the max of their children and the obstacle boxes a fresh
// computation gives, nothing left to prune, known bounds tight.
#include "octree/bounded_tree.hpp"
#include "octree/decay.hpp"
#include "octree/octree_cell.hpp"
#include "octree/point_extent.hpp"
#include "octree/region_edit.hpp"
#include "octree/traverse.hpp"
#include "narrowphase/narrow_phase.hpp"
#include "world/shape_region.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <map>
#include <random>
#include <vector>

namespace {

using namespace octoprox;

using Key = std::array<int32_t, 3>;
struct Cell {
    float log_odds = 0.0f;
    uint32_t extent = 0;  // in the finest cell's slots, as expansion passes it down
    bool operator==(const Cell &o) const { return log_odds == o.log_odds && extent == o.extent; }
};
using Dense = std::map<Key, Cell>;

void add_leaf(Dense &dense, const CellKey &cube, float log_odds, uint32_t extent) {
    if (cube.depth == kTreeDepth) {
        dense[Key{cube.key[0], cube.key[1], cube.key[2]}] = Cell{log_odds, extent};
        return;
    }
    for (int i = 0; i < 8; ++i)
        add_leaf(dense, cube.child(i), log_odds, extent::valid(extent) ? extent::to_child(extent, i) : 0);
}

// Every finest cell of the map (the maps here are small).
Dense dense_of(const SensorOctree &tree) {
    Dense dense;
    const OctreeView view = tree.view();
    for_each_leaf(view, [&](OctreeView::NodeRef node, const CellKey &cube) {
        add_leaf(dense, cube, view.log_odds(node), view.point_extent(node));
    });
    return dense;
}

void check_structure(const SensorOctree &tree) {
    const BoundedOcTree &t = tree.octomap_tree();
    EXPECT_EQ(t.size(), t.calcNumNodes());
    size_t inner = 0;
    const float threshold = tree.view().bounds_threshold();
    std::function<void(const BoundedNode *)> walk = [&](const BoundedNode *node) {
        if (!node->has_child_array()) return;
        ++inner;
        float max = -std::numeric_limits<float>::infinity();
        bool any = false;
        for (unsigned i = 0; i < 8; ++i)
            if (t.nodeChildExists(node, i)) {
                any = true;
                max = std::max(max, t.getNodeChild(node, i)->getLogOdds());
                walk(t.getNodeChild(node, i));
            }
        ASSERT_TRUE(any) << "a node with an empty child block";
        EXPECT_EQ(node->getLogOdds(), max);
        EXPECT_FALSE(t.isNodeCollapsible(node)) << "a node left unpruned";
        BoundedNode fresh;
        fresh.copyData(*node);
        fresh.child_pointers() = const_cast<BoundedNode *>(node)->child_pointers();
        {
            const BoundsScope scope(threshold);
            fresh.updateOccupancyChildren();
        }
        EXPECT_EQ(fresh.packed_bounds(), node->packed_bounds());
        fresh.child_pointers() = nullptr;
    };
    if (t.getRoot() != nullptr) walk(t.getRoot());
    EXPECT_EQ(t.child_blocks().blocks_in_use(), inner);
    const TreeStats s = tree.stats();
    if (!s.has_known) {
        EXPECT_TRUE(tree.known_bounds().empty());
        return;
    }
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_NEAR(tree.known_bounds().lo[axis], s.known_min[axis], 1e-9);
        EXPECT_NEAR(tree.known_bounds().hi[axis], s.known_max[axis], 1e-9);
    }
}

// A map of random frames at 0.25 m: rays from a few origins (free space
// clamped and pruned in places), blocks of endpoints (occupied leaves
// pruned, with point extents) and scattered hits.
std::unique_ptr<SensorOctree> random_map(std::mt19937_64 &rng) {
    auto tree = unit::empty_octree(0.25);
    std::uniform_real_distribution<double> coord(-2.5, 2.5);
    // Sensors near the origin: the cells around it are crossed in every
    // frame, clamped free and pruned.
    for (int frame = 0; frame < 7; ++frame) {
        std::vector<double> xyz;
        for (int i = 0; i < 400; ++i)
            for (double v : {coord(rng), coord(rng), coord(rng)}) xyz.push_back(v);
        InsertSettings settings;
        settings.sensor_pose.translation = Vec3(0.1 + coord(rng) * 0.02, 0.1 + coord(rng) * 0.02, 0.1);
        unit::insert_xyz(*tree, xyz, settings);
    }
    // A block of 4 x 4 x 4 cells, hit until clamped: pruned occupied leaves.
    std::vector<double> block;
    for (int x = 0; x < 8; ++x)
        for (int y = 0; y < 8; ++y)
            for (int z = 0; z < 8; ++z)
                for (double v : {1.0 + 0.11 * x + 0.05, -2.0 + 0.11 * y + 0.05, 0.0 + 0.11 * z + 0.05}) block.push_back(v);
    InsertSettings endpoints;
    endpoints.raycast = false;
    for (int i = 0; i < 8; ++i) unit::insert_xyz(*tree, block, endpoints);
    return tree;
}

CellRange random_range(std::mt19937_64 &rng) {
    std::uniform_int_distribution<int32_t> key(kKeyCenter - 13, kKeyCenter + 13);
    CellRange range;
    for (int axis = 0; axis < 3; ++axis) {
        int32_t a = key(rng), b = key(rng);
        if (a > b) std::swap(a, b);
        if (rng() % 4 == 0) a = b = kKeyCenter + 4 * static_cast<int32_t>(rng() % 4) - 8;  // a plane of cells
        if (rng() % 4 == 0) a = kKeyCenter + 4 * (a / 4 - kKeyCenter / 4), b = a + 3;  // a pruned leaf's faces
        range.lo[axis] = a, range.hi[axis] = b;
    }
    return range;
}

bool inside(const CellRange &range, const Key &k) {
    const uint32_t key[3] = {static_cast<uint32_t>(k[0]), static_cast<uint32_t>(k[1]), static_cast<uint32_t>(k[2])};
    return range.contains(key);
}

// Every cell of the window around the maps, for free fills.
template <class Visit>
void for_each_window_cell(Visit &&visit) {
    for (int32_t x = kKeyCenter - 16; x < kKeyCenter + 16; ++x)
        for (int32_t y = kKeyCenter - 16; y < kKeyCenter + 16; ++y)
            for (int32_t z = kKeyCenter - 16; z < kKeyCenter + 16; ++z) visit(Key{x, y, z});
}

void expect_dense_equal(const Dense &actual, const Dense &expected, const char *what) {
    EXPECT_EQ(actual.size(), expected.size()) << what;
    int reported = 0;
    for (const auto &[key, cell] : expected) {
        const auto found = actual.find(key);
        if (found != actual.end() && found->second == cell) continue;
        if (++reported > 5) break;
        ADD_FAILURE() << what << ": cell " << key[0] - kKeyCenter << " " << key[1] - kKeyCenter << " "
                      << key[2] - kKeyCenter << " expected " << cell.log_odds << "/" << cell.extent << ", got "
                      << (found == actual.end() ? std::string("unknown")
                                                : std::to_string(found->second.log_odds) + "/" +
                                                      std::to_string(found->second.extent));
    }
}

// The random maps hold what the edits must handle: pruned leaves, free
// and occupied, and point extents.
TEST(MapEdit, RandomMapsHoldPrunedLeavesAndExtents) {
    std::mt19937_64 rng(45);
    auto tree = random_map(rng);
    int pruned_free = 0, pruned_occupied = 0;
    for_each_leaf(tree->view(), [&](OctreeView::NodeRef node, const CellKey &cube) {
        if (cube.depth == kTreeDepth) return;
        (tree->view().log_odds(node) >= tree->view().bounds_threshold() ? pruned_occupied : pruned_free) += 1;
    });
    EXPECT_GT(pruned_free, 0);
    EXPECT_GT(pruned_occupied, 0);
    EXPECT_GT(tree->stats().leaves_with_extent, 0u);
}

TEST(MapEdit, ClearRegionMatchesEveryCell) {
    std::mt19937_64 rng(46);
    int changed = 0;
    for (int trial = 0; trial < 24; ++trial) {
        auto tree = random_map(rng);
        const Dense before = dense_of(*tree);
        const CellRange range = random_range(rng);
        const bool to_free = trial % 2 == 0;
        tree->clear_region(CellRangeRegion(range, false), to_free);
        Dense expected;
        const float free_value = tree->octomap_tree().getClampingThresMinLog();
        for (const auto &[key, cell] : before)
            if (!inside(range, key)) expected[key] = cell;
        if (to_free)
            for_each_window_cell([&](const Key &key) {
                if (inside(range, key)) expected[key] = Cell{free_value, 0};
            });
        const Dense after = dense_of(*tree);
        changed += !(after.size() == before.size() && std::equal(after.begin(), after.end(), before.begin()));
        expect_dense_equal(after, expected, to_free ? "clear to free" : "clear to unknown");
        check_structure(*tree);
    }
    EXPECT_GT(changed, 18);
}

TEST(MapEdit, CropKeepsTheBoxAlone) {
    std::mt19937_64 rng(47);
    for (int trial = 0; trial < 12; ++trial) {
        auto tree = random_map(rng);
        const Dense before = dense_of(*tree);
        const CellRange range = random_range(rng);
        const size_t kept = blocks_after_removal(tree->octomap_tree(), CellRangeRegion(range, true));
        tree->crop(range);
        EXPECT_EQ(tree->octomap_tree().child_blocks().blocks_in_use(), kept);
        Dense expected;
        for (const auto &[key, cell] : before)
            if (inside(range, key)) expected[key] = cell;
        expect_dense_equal(dense_of(*tree), expected, "crop");
        check_structure(*tree);
    }
}

TEST(MapEdit, CropGivesMemoryBack) {
    std::mt19937_64 rng(48);
    auto tree = unit::empty_octree(0.02);
    std::uniform_real_distribution<double> coord(-3.0, 3.0);
    std::vector<double> xyz;
    for (int i = 0; i < 60000; ++i)
        for (double v : {coord(rng), coord(rng), coord(rng) * 0.3}) xyz.push_back(v);
    InsertSettings endpoints;
    endpoints.raycast = false;
    unit::insert_xyz(*tree, xyz, endpoints);
    const uint64_t full = tree->stats().memory_bytes;
    CellRange window;
    for (int axis = 0; axis < 3; ++axis) window.lo[axis] = kKeyCenter - 10, window.hi[axis] = kKeyCenter + 9;
    tree->crop(window);
    const uint64_t cropped = tree->stats().memory_bytes;
    EXPECT_LT(cropped, full / 20) << full << " bytes before, " << cropped << " after";
    EXPECT_LT(cropped, uint64_t{200} << 10);
    check_structure(*tree);
}

TEST(MapEdit, DecayMatchesLogOddsReference) {
    std::mt19937_64 rng(49);
    const double amounts[] = {0.05, 0.3, 0.4054651, 0.8472979, 1.5, 4.0};
    for (int trial = 0; trial < 18; ++trial) {
        auto tree = random_map(rng);
        const Dense before = dense_of(*tree);
        const double amount = amounts[trial % 6];
        const float occupied = tree->view().bounds_threshold();
        tree->decay(amount);
        Dense expected;
        for (const auto &[key, cell] : before) {
            const double v = cell.log_odds;
            const float next = static_cast<float>(v > 0 ? v - amount : v + amount);
            if (v == 0 || (v > 0 && !(next > 0)) || (v < 0 && !(next < 0))) continue;  // never across 0
            expected[key] = Cell{next, next >= occupied ? cell.extent : 0u};
        }
        expect_dense_equal(dense_of(*tree), expected, "decay");
        check_structure(*tree);
    }
}

TEST(MapEdit, RepeatedDecayEmptiesTheMap) {
    std::mt19937_64 rng(50);
    auto tree = random_map(rng);
    for (int i = 0; i < 40 && tree->octomap_tree().getRoot() != nullptr; ++i) tree->decay(0.1);
    EXPECT_EQ(tree->octomap_tree().getRoot(), nullptr);
    EXPECT_EQ(tree->octomap_tree().size(), 0u);
    EXPECT_TRUE(tree->known_bounds().empty());
}

TEST(MapEdit, BoundedInsertChangesCellsInsideAlone) {
    std::mt19937_64 rng(51);
    std::uniform_real_distribution<double> coord(-2.5, 2.5);
    for (int trial = 0; trial < 12; ++trial) {
        std::mt19937_64 seed_a(100 + trial), seed_b(100 + trial);
        auto bounded = random_map(seed_a);
        auto unbounded = random_map(seed_b);  // the same map
        const Dense before = dense_of(*bounded);
        std::vector<double> xyz;
        for (int i = 0; i < 200; ++i)
            for (double v : {coord(rng), coord(rng), coord(rng)}) xyz.push_back(v);
        const PointSource points{reinterpret_cast<const unsigned char *>(xyz.data()), xyz.size() / 3, 24, true};
        InsertSettings settings;
        settings.raycast = trial % 3 != 0;
        settings.max_range = trial % 4 == 1 ? 1.5 : -1.0;
        unbounded->insert(points, settings);
        const CellRange range = random_range(rng);
        settings.bounds = &range;
        bounded->insert(points, settings);
        Dense expected;
        for (const auto &[key, cell] : before)
            if (!inside(range, key)) expected[key] = cell;
        for (const auto &[key, cell] : dense_of(*unbounded))
            if (inside(range, key)) expected[key] = cell;
        expect_dense_equal(dense_of(*bounded), expected, "bounded insert");
        check_structure(*bounded);
    }
}

// The cells a few shapes touch, by the narrow phase on every cell of the
// window.
TEST(MapEdit, ClearShapesMatchesEveryCell) {
    std::mt19937_64 rng(52);
    std::uniform_real_distribution<double> unit_interval(0.0, 1.0);
    for (int trial = 0; trial < 10; ++trial) {
        auto tree = random_map(rng);
        const Dense before = dense_of(*tree);
        std::vector<ShapeDef> defs(3);
        defs[0].kind = ShapeKind::kBox;
        defs[0].half_size = Vec3(0.3 + unit_interval(rng), 0.2 + 0.5 * unit_interval(rng), 0.25);
        defs[1].kind = ShapeKind::kSphere;
        defs[1].radius = 0.2 + 0.6 * unit_interval(rng);
        defs[1].local.translation = Vec3(0.5, -0.25, 0.5);  // on cell faces at 0.25 m
        defs[2].kind = ShapeKind::kCylinder;
        defs[2].radius = 0.3;
        defs[2].half_length = 0.5;
        defs[2].local.translation = Vec3(-0.7, 0.3, 0.1);
        Pose pose;
        pose.translation = Vec3(unit_interval(rng) - 0.5, unit_interval(rng) - 0.5, unit_interval(rng) - 0.5);
        if (trial % 2 == 1) pose.rotation = Eigen::AngleAxisd(unit_interval(rng) * 3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
        std::vector<PlacedShape> placed(defs.size());
        for (size_t i = 0; i < defs.size(); ++i) place_shape(defs[i], pose, 0.0, true, placed[i]);
        const bool to_free = trial % 2 == 0;
        tree->clear_region(ShapesRegion(defs, pose, 0.25), to_free);
        const auto touched = [&](const Key &key) {
            CellKey cube;
            for (int axis = 0; axis < 3; ++axis) cube.key[axis] = static_cast<uint16_t>(key[axis]);
            cube.depth = kTreeDepth;
            const Aabb box = cell_box(cube, 0.25);
            uint64_t tests = 0;
            for (const PlacedShape &shape : placed)
                if (shape_touches_cell(shape, box.center(), box.half_extent(), tests)) return true;
            return false;
        };
        Dense expected;
        const float free_value = tree->octomap_tree().getClampingThresMinLog();
        for (const auto &[key, cell] : before)
            if (!touched(key)) expected[key] = cell;
        if (to_free)
            for_each_window_cell([&](const Key &key) {
                if (touched(key)) expected[key] = Cell{free_value, 0};
            });
        expect_dense_equal(dense_of(*tree), expected, to_free ? "shapes to free" : "shapes to unknown");
        check_structure(*tree);
    }
}

}  // namespace
