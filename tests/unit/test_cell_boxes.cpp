// Cell extraction (T_1,1) against a plain walk over every leaf: the same
// cells in each band, with the boxes of the query engines.
#include "octree/cell_boxes.hpp"

#include "octree/octree_cell.hpp"
#include "octree/traverse.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

using octoprox::CellBands;
using octoprox::CellBoxes;
using octoprox::CellKey;
using octoprox::SensorOctree;

namespace {

using Row = std::tuple<int, int, int, int, float>;  // key, depth, log-odds

std::vector<Row> rows_of(const CellBoxes &cells) {
    std::vector<Row> rows;
    for (size_t i = 0; i < cells.size(); ++i) {
        const CellKey &k = cells.keys[i];
        rows.emplace_back(k.key[0], k.key[1], k.key[2], k.depth, cells.log_odds[i]);
    }
    std::sort(rows.begin(), rows.end());
    return rows;
}

// Every leaf, classified one by one.
void expected_rows(const SensorOctree &tree, const CellBands &bands, std::vector<Row> &occupied,
                   std::vector<Row> &uncertain) {
    const octoprox::OctreeView view = tree.view();
    octoprox::for_each_leaf(view, [&](octoprox::OctreeView::NodeRef node, const CellKey &k) {
        const float l = view.log_odds(node);
        const Row row(k.key[0], k.key[1], k.key[2], k.depth, l);
        if (l >= bands.threshold_log_odds) occupied.push_back(row);
        else if (l >= bands.free_log_odds) uncertain.push_back(row);
    });
    std::sort(occupied.begin(), occupied.end());
    std::sort(uncertain.begin(), uncertain.end());
}

void expect_boxes_match_keys(const CellBoxes &cells, double resolution) {
    ASSERT_EQ(cells.boxes.size(), cells.keys.size());
    ASSERT_EQ(cells.log_odds.size(), cells.keys.size());
    for (size_t i = 0; i < cells.size(); ++i) {
        const octoprox::Aabb expected = octoprox::cell_box(cells.keys[i], resolution);
        ASSERT_EQ(cells.boxes[i].lo, expected.lo);
        ASSERT_EQ(cells.boxes[i].hi, expected.hi);
    }
}

// A frame with rays: free, uncertain (one miss between the thresholds) and
// occupied cells at several depths after OctoMap's pruning.
std::unique_ptr<SensorOctree> mixed_octree() {
    octoprox::OctreeParams params;
    params.resolution = 0.1;
    params.occupied_threshold = 0.6;
    params.free_threshold = 0.3;  // one miss (0.4) stays uncertain, two are free
    auto tree = std::make_unique<SensorOctree>(params);
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
    for (int frame = 0; frame < 3; ++frame) {
        std::vector<double> xyz;
        for (int i = 0; i < 400; ++i) xyz.insert(xyz.end(), {coordinate(rng), coordinate(rng), 2.5 + 0.1 * frame});
        octoprox::PointSource points{reinterpret_cast<const unsigned char *>(xyz.data()), xyz.size() / 3,
                                     3 * sizeof(double), true};
        octoprox::InsertSettings settings;
        settings.sensor_pose.translation = octoprox::Vec3(0.1 * frame, 0, -2.0);
        tree->insert(points, settings);
    }
    return tree;
}

CellBands bands_of(const SensorOctree &tree) {
    CellBands bands;
    bands.threshold_log_odds = static_cast<float>(octoprox::log_odds(tree.params().occupied_threshold));
    bands.free_log_odds = static_cast<float>(octoprox::log_odds(tree.params().free_threshold));
    return bands;
}

}  // namespace

TEST(CellBoxes, BandsMatchALeafByLeafWalk) {
    const auto tree = mixed_octree();
    const CellBands bands = bands_of(*tree);
    std::vector<Row> occupied, uncertain;
    expected_rows(*tree, bands, occupied, uncertain);
    ASSERT_GT(occupied.size(), 100u);
    ASSERT_GT(uncertain.size(), 100u);

    CellBoxes got_occupied, got_uncertain;
    octoprox::extract_cell_boxes(*tree, bands, got_occupied, &got_uncertain);
    EXPECT_EQ(rows_of(got_occupied), occupied);
    EXPECT_EQ(rows_of(got_uncertain), uncertain);
    expect_boxes_match_keys(got_occupied, tree->params().resolution);
    expect_boxes_match_keys(got_uncertain, tree->params().resolution);

    // Without the uncertain output, the occupied cells alone (and refilling
    // clears what was there).
    octoprox::extract_cell_boxes(*tree, bands, got_occupied, nullptr);
    EXPECT_EQ(rows_of(got_occupied), occupied);
    // Other thresholds: everything observed at or above the lowest log-odds.
    CellBands everything{-100.0f, -100.0f};
    std::vector<Row> all, none;
    expected_rows(*tree, everything, all, none);
    octoprox::extract_cell_boxes(*tree, everything, got_occupied, &got_uncertain);
    EXPECT_EQ(rows_of(got_occupied), all);
    EXPECT_TRUE(got_uncertain.boxes.empty());
}

TEST(CellBoxes, EmptyTree) {
    SensorOctree tree{octoprox::OctreeParams()};
    CellBoxes occupied, uncertain;
    occupied.add(octoprox::Aabb(), CellKey(), 1.0f);
    octoprox::extract_cell_boxes(tree, bands_of(tree), occupied, &uncertain);
    EXPECT_EQ(occupied.size(), 0u);
    EXPECT_EQ(uncertain.size(), 0u);
}

TEST(CellBoxes, SyntheticSceneHasEveryCell) {
    const auto tree = unit::synthetic_octree(3);
    const CellBoxes cells = unit::occupied_cells(*tree);
    EXPECT_EQ(cells.size(), 7784u);
    EXPECT_EQ(cells.size(), tree->stats().leaves[octoprox::kOccupied]);
    for (const octoprox::Aabb &b : cells.boxes) {
        ASSERT_NEAR(b.longest_edge(), 0.2, 1e-12);
        ASSERT_GE(b.lo.minCoeff(), -20.0 - 1e-9);
        ASSERT_LE(b.hi.maxCoeff(), 20.0 + 1e-9);
    }
}
