// The obstacle grid (octree/obstacle_grid.hpp) and the sphere query that
// reads it (query/spheres/sphere_grid.hpp): the grid holds exactly the
// finest cells of the obstacle leaves, its clearance never exceeds the true
// distance, and a sphere answered through the grid gets the descent's
// answer, bit for bit: random spheres, spheres touching cells exactly (on
// faces, edges and corners), pruned leaves, other thresholds, point
// extents, and maps changed after the grid was built.
#include "octree/obstacle_grid.hpp"
#include "octree/traverse.hpp"
#include "query/spheres/sphere_grid.hpp"
#include "query/spheres/sphere_query.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace {

using octoprox::CellKey;
using octoprox::GridAnswer;
using octoprox::ObstacleGrid;
using octoprox::OctreeView;
using octoprox::SensorOctree;
using octoprox::Vec3;
using Key = std::tuple<int32_t, int32_t, int32_t>;

constexpr double kRes = 0.05;

octoprox::InsertSettings from(const Vec3 &sensor) {
    octoprox::InsertSettings settings;
    settings.sensor_pose.translation = sensor;
    return settings;
}

// A cloud on a few random planes and in a few solid blocks (whose cells,
// hit in every frame, clamp and prune into coarser leaves), inserted
// `frames` times by ray casting from the origin.
std::unique_ptr<SensorOctree> random_map(uint64_t seed, int frames) {
    auto tree = unit::empty_octree(kRes);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> xyz;
    for (int plane = 0; plane < 4; ++plane) {
        const Vec3 origin(2.0 + u(rng), u(rng), u(rng)), a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
        for (int i = 0; i < 3000; ++i) {
            const Vec3 p = origin + a * u(rng) + b * u(rng);
            xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
        }
    }
    for (int block = 0; block < 3; ++block) {
        // 8 x 8 x 8 cells, aligned so that they prune into one leaf.
        const Vec3 corner(kRes * 8 * std::floor(4.0 + 4 * u(rng)), kRes * 8 * std::floor(4 * u(rng)),
                          kRes * 8 * std::floor(4 * u(rng)));
        for (int x = 0; x < 8; ++x)
            for (int y = 0; y < 8; ++y)
                for (int z = 0; z < 8; ++z) {
                    const Vec3 p = corner + kRes * Vec3(x + 0.5, y + 0.5, z + 0.5);
                    xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
                }
    }
    for (int f = 0; f < frames; ++f) unit::insert_xyz(*tree, xyz, from(Vec3::Zero()));
    return tree;
}

float map_threshold(const SensorOctree &tree) { return tree.view().bounds_threshold(); }

// The finest cells of every leaf at or above the threshold.
std::set<Key> obstacle_cells(const SensorOctree &tree, float threshold, size_t &coarse_leaves) {
    std::set<Key> cells;
    coarse_leaves = 0;
    octoprox::for_each_leaf(tree.view(), [&](OctreeView::NodeRef node, const CellKey &cell) {
        if (tree.view().log_odds(node) < threshold) return;
        const int32_t w = cell.width_in_cells();
        if (w > 1) ++coarse_leaves;
        for (int32_t x = 0; x < w; ++x)
            for (int32_t y = 0; y < w; ++y)
                for (int32_t z = 0; z < w; ++z) cells.emplace(cell.key[0] + x, cell.key[1] + y, cell.key[2] + z);
    });
    return cells;
}

// The grid's cells in the key box [lo - 8, hi + 8] of `near`, read in
// windows of 32 cells (a question spans at most kMaxBricksAcross bricks).
std::set<Key> grid_cells(const ObstacleGrid &grid, const std::set<Key> &near) {
    std::set<Key> cells;
    if (near.empty()) return cells;
    int32_t lo[3] = {INT32_MAX, INT32_MAX, INT32_MAX}, hi[3] = {0, 0, 0};
    for (const Key &k : near) {
        const int32_t c[3] = {std::get<0>(k), std::get<1>(k), std::get<2>(k)};
        for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], c[a] - 8), hi[a] = std::max(hi[a], c[a] + 8);
    }
    for (int32_t x = lo[0]; x <= hi[0]; x += 32)
        for (int32_t y = lo[1]; y <= hi[1]; y += 32)
            for (int32_t z = lo[2]; z <= hi[2]; z += 32) {
                const int32_t from[3] = {x, y, z}, to[3] = {x + 31, y + 31, z + 31};
                const GridAnswer answer = grid.ask_cells(from, to, [&](int32_t cx, int32_t cy, int32_t cz) {
                    cells.emplace(cx, cy, cz);
                    return GridAnswer::kNo;
                });
                EXPECT_EQ(answer, GridAnswer::kNo);
            }
    return cells;
}

octoprox::SphereSettings settings_for(float threshold, bool point_extents) {
    octoprox::SphereSettings s;
    s.threshold_log_odds = threshold;
    s.point_extents = point_extents;
    return s;
}

// Both ways of answering a sphere agree; returns whether the grid decided.
bool expect_same(const SensorOctree &tree, const ObstacleGrid &grid, const Vec3 &center, double radius,
                 const octoprox::SphereSettings &settings) {
    const bool with_grid = octoprox::sphere_collides(tree, &grid, center, radius, settings);
    const bool descent = octoprox::sphere_collides(tree, nullptr, center, radius, settings);
    EXPECT_EQ(with_grid, descent) << "centre " << center.transpose() << " radius " << radius;
    return octoprox::sphere_on_grid(grid, center, radius, settings.point_extents) != GridAnswer::kUndecided;
}

Vec3 cell_corner(const Key &k) {
    return kRes * Vec3(std::get<0>(k) - octoprox::kKeyCenter, std::get<1>(k) - octoprox::kKeyCenter,
                       std::get<2>(k) - octoprox::kKeyCenter);
}

TEST(ObstacleGrid, HoldsExactlyTheObstacleCells) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
        const auto tree = random_map(seed, 6);
        for (float threshold : {map_threshold(*tree), 0.0f, 2.0f}) {
            size_t coarse = 0;
            const std::set<Key> expected = obstacle_cells(*tree, threshold, coarse);
            const auto grid = ObstacleGrid::build(tree->view(), threshold, size_t(1) << 30);
            ASSERT_NE(grid, nullptr);
            EXPECT_EQ(grid_cells(*grid, expected), expected) << "seed " << seed << " threshold " << threshold;
            if (threshold == map_threshold(*tree)) {
                EXPECT_GT(coarse, 0u) << "no pruned obstacle leaf to test";
            }
        }
    }
}

TEST(ObstacleGrid, ClearanceIsALowerBound) {
    const auto tree = random_map(7, 2);
    const float threshold = map_threshold(*tree);
    size_t coarse = 0;
    const std::set<Key> cells = obstacle_cells(*tree, threshold, coarse);
    const auto grid = ObstacleGrid::build(tree->view(), threshold, size_t(1) << 30);
    ASSERT_NE(grid, nullptr);
    std::mt19937_64 rng(11);
    std::uniform_int_distribution<int32_t> offset(-80, 80);
    const std::vector<Key> all(cells.begin(), cells.end());
    size_t positive = 0, outside_box = 0;
    for (int i = 0; i < 3000; ++i) {
        const Key &near = all[rng() % all.size()];
        const int32_t key[3] = {std::get<0>(near) + offset(rng), std::get<1>(near) + offset(rng),
                                std::get<2>(near) + offset(rng)};
        const int32_t clearance = grid->clearance(key);
        if (clearance == 0) continue;
        ++positive;
        outside_box += clearance % 4 != 0;  // inside the box it counts whole bricks
        // The gap between the cell and the nearest obstacle cell, on the
        // axis where it is largest (a lower bound of the Euclidean gap).
        int64_t nearest = INT64_MAX;
        for (const Key &c : cells) {
            const int32_t other[3] = {std::get<0>(c), std::get<1>(c), std::get<2>(c)};
            int64_t gap = 0;
            for (int a = 0; a < 3; ++a) gap = std::max<int64_t>(gap, std::abs(other[a] - key[a]) - 1);
            nearest = std::min(nearest, gap);
        }
        ASSERT_LE(clearance, nearest) << "cell " << key[0] << " " << key[1] << " " << key[2];
    }
    EXPECT_GT(positive, 100u);
    EXPECT_GT(outside_box, 100u);
}

TEST(SphereGrid, RandomSpheresGetTheDescentsAnswer) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
        const auto tree = random_map(seed, seed == 1 ? 1 : 8);
        std::mt19937_64 rng(seed * 101);
        for (float threshold : {map_threshold(*tree), 0.5f}) {
            const auto grid = ObstacleGrid::build(tree->view(), threshold, size_t(1) << 30);
            ASSERT_NE(grid, nullptr);
            size_t coarse = 0;
            const std::set<Key> cells = obstacle_cells(*tree, threshold, coarse);
            const std::vector<Key> all(cells.begin(), cells.end());
            std::uniform_real_distribution<double> jitter(-0.4, 0.4), radius(0.0, 0.2);
            for (bool extents : {false, true}) {
                const auto settings = settings_for(threshold, extents);
                size_t decided = 0, collided = 0;
                const int count = 4000;
                for (int i = 0; i < count; ++i) {
                    const Vec3 c = cell_corner(all[rng() % all.size()]) + Vec3(jitter(rng), jitter(rng), jitter(rng));
                    const double r = i % 50 == 0 ? 0.0 : i % 97 == 0 ? 4.0 : radius(rng);
                    decided += expect_same(*tree, *grid, c, r, settings);
                    collided += octoprox::sphere_collides(*tree, grid.get(), c, r, settings);
                }
                EXPECT_GT(collided, size_t(count / 10));
                EXPECT_LT(collided, size_t(count * 9 / 10));
                if (!extents) {
                    EXPECT_GT(decided, size_t(count * 9 / 10)) << "the grid decided too few spheres";
                }
            }
        }
    }
}

// Spheres touching an obstacle cell exactly, or missing it by a hair, at
// its faces, edges and corners: the touch tolerance (1e-9 m) decides.
TEST(SphereGrid, TouchingSpheresGetTheDescentsAnswer) {
    const auto tree = random_map(5, 3);
    const float threshold = map_threshold(*tree);
    const auto grid = ObstacleGrid::build(tree->view(), threshold, size_t(1) << 30);
    ASSERT_NE(grid, nullptr);
    size_t coarse = 0;
    const std::set<Key> cells = obstacle_cells(*tree, threshold, coarse);
    std::mt19937_64 rng(3);
    const std::vector<Key> all(cells.begin(), cells.end());
    const double gaps[] = {0.0, 0.5e-9, 0.999e-9, 1e-9, 1.001e-9, 2e-9, 1e-7, -1e-12};
    const auto settings = settings_for(threshold, false);
    for (int i = 0; i < 400; ++i) {
        const Key k = all[rng() % all.size()];
        const Vec3 lo = cell_corner(k), hi = lo + Vec3::Constant(kRes);
        // A direction away from the cell: each axis below, inside or above.
        const int side[3] = {int(rng() % 3) - 1, int(rng() % 3) - 1, int(rng() % 3) - 1};
        for (double radius : {0.0, 0.02, 0.05, 0.1}) {
            for (double gap : gaps) {
                Vec3 c;
                double outward2 = 0.0;
                for (int a = 0; a < 3; ++a) c[a] = side[a] < 0 ? lo[a] : side[a] > 0 ? hi[a] : 0.5 * (lo[a] + hi[a]);
                for (int a = 0; a < 3; ++a) outward2 += side[a] * side[a];
                if (outward2 == 0.0) continue;
                const double along = (radius + gap) / std::sqrt(outward2);
                for (int a = 0; a < 3; ++a) c[a] += side[a] * along;
                expect_same(*tree, *grid, c, radius, settings);
            }
        }
    }
}

// The map keeps one grid for its state: a change builds the next.
TEST(SphereGrid, MapChangesRebuildTheGrid) {
    auto tree = random_map(9, 1);
    const float threshold = map_threshold(*tree);
    const auto before = tree->obstacle_grid(threshold);
    EXPECT_EQ(before, tree->obstacle_grid(threshold));
    std::vector<double> wall;
    for (int y = -20; y <= 20; ++y)
        for (int z = -20; z <= 20; ++z) wall.insert(wall.end(), {1.2, y * 0.02, z * 0.02});
    unit::insert_xyz(*tree, wall, from(Vec3::Zero()));
    const auto after = tree->obstacle_grid(threshold);
    ASSERT_NE(after, nullptr);
    EXPECT_NE(before, after);
    const Vec3 on_wall(1.2, 0.0, 0.0);
    EXPECT_TRUE(octoprox::sphere_collides(*tree, after.get(), on_wall, 0.01, settings_for(threshold, false)));
    size_t coarse = 0;
    const std::set<Key> expected = obstacle_cells(*tree, threshold, coarse);
    EXPECT_EQ(grid_cells(*after, expected), expected);
}

TEST(ObstacleGrid, EmptyAndOversizedMaps) {
    octoprox::OctreeParams params;
    params.resolution = kRes;
    SensorOctree empty(params);
    const auto grid = ObstacleGrid::build(empty.view(), map_threshold(empty), size_t(1) << 30);
    ASSERT_NE(grid, nullptr);
    EXPECT_TRUE(grid_cells(*grid, {Key(32768, 32768, 32768)}).empty());
    EXPECT_FALSE(octoprox::sphere_collides(empty, grid.get(), Vec3::Zero(), 1.0, settings_for(map_threshold(empty), false)));
    // Two obstacles 600 m apart on every axis: too large a box for a small
    // budget (endpoints only, not 12,000-cell rays).
    octoprox::InsertSettings endpoints = from(Vec3::Zero());
    endpoints.raycast = false;
    unit::insert_xyz(empty, {-300.0, -300.0, -300.0, 300.0, 300.0, 300.0}, endpoints);
    EXPECT_EQ(ObstacleGrid::build(empty.view(), map_threshold(empty), size_t(1) << 20), nullptr);
}

}  // namespace
