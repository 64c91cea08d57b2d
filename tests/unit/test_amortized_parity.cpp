// The amortized engine answers every query itself, as the direct engine
// does: called directly (no C shim, no fallback possible) on a ray-cast map
// with occupied, uncertain, free and unknown cells, against the
// DirectEngine: cost (totals, every box), OPX_UNKNOWN_OCCUPIED
// contacts and distances, penetration per contact and signed distances.
// The unknown cubes tile the map cube with the leaves; the cost and unknown
// trees are built once per frame, on first need only.
#include "octree/cell_boxes.hpp"
#include "octree/octree_cell.hpp"
#include "octree/traverse.hpp"
#include "query/amortized/amortized_engine.hpp"
#include "query/direct/direct_engine.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <tuple>

namespace {

using namespace octoprox;

// Rays from below up to random points: free cones, uncertain cells (one
// miss, between the thresholds), occupied ends, unknown all around.
std::unique_ptr<SensorOctree> mixed_octree(uint64_t seed) {
    OctreeParams params;
    params.resolution = 0.1;
    params.occupied_threshold = 0.6;
    params.free_threshold = 0.3;
    auto tree = std::make_unique<SensorOctree>(params);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
    for (int frame = 0; frame < 3; ++frame) {
        std::vector<double> xyz;
        for (int i = 0; i < 300; ++i) xyz.insert(xyz.end(), {coordinate(rng), coordinate(rng), 1.5 + 0.1 * frame});
        PointSource points{reinterpret_cast<const unsigned char *>(xyz.data()), xyz.size() / 3, 3 * sizeof(double), true};
        InsertSettings settings;
        settings.sensor_pose.translation = Vec3(0.1 * frame, 0.0, -1.5);
        tree->insert(points, settings);
    }
    return tree;
}

// Three links: a sphere, a rotated box, a capsule.
LinkSet make_robot() {
    LinkSet links;
    ShapeDef sphere;
    sphere.kind = ShapeKind::kSphere, sphere.radius = 0.25;
    ShapeDef box;
    box.kind = ShapeKind::kBox, box.half_size = Vec3(0.3, 0.1, 0.2);
    ShapeDef capsule;
    capsule.kind = ShapeKind::kCapsule, capsule.radius = 0.08, capsule.half_length = 0.3;
    for (const ShapeDef &def : {sphere, box, capsule}) links.add_shape(links.add_link("l"), def);
    links.set_padding(0.01);
    return links;
}

void random_poses(LinkSet &links, std::mt19937_64 &rng) {
    std::uniform_real_distribution<double> coordinate(-2.2, 2.2), height(-1.8, 2.0), angle(-3.2, 3.2);
    std::vector<Pose> poses(links.link_count());
    for (Pose &pose : poses) {
        pose.translation = Vec3(coordinate(rng), coordinate(rng), height(rng));
        pose.rotation = (Eigen::AngleAxisd(angle(rng), Vec3::UnitZ()) * Eigen::AngleAxisd(angle(rng), Vec3::UnitX()))
                            .toRotationMatrix();
    }
    links.set_poses(poses);
}

CollisionSettings cost_settings(const SensorOctree &tree, bool unknown_occupied) {
    CollisionSettings s;
    s.threshold_log_odds = static_cast<float>(log_odds(tree.params().occupied_threshold));
    s.free_log_odds = static_cast<float>(log_odds(tree.params().free_threshold));
    s.unknown_occupied = unknown_occupied;
    s.max_contacts = UINT32_MAX;
    s.cost = true;
    s.unknown_probability = 0.5;
    s.region = Aabb{Vec3(-1.5, -1.5, -1.0), Vec3(1.5, 1.5, 1.7)};
    return s;
}

DistanceSettings distance_settings(const SensorOctree &tree, bool unknown_occupied, bool signed_distance) {
    DistanceSettings s;
    s.threshold_log_odds = static_cast<float>(log_odds(tree.params().occupied_threshold));
    s.unknown_occupied = unknown_occupied;
    s.signed_distance = signed_distance;
    return s;
}

// A contact as (link, shape, cell center, size, class, probability, depth).
using ContactRow = std::tuple<uint32_t, uint32_t, double, double, double, double, int, double, double>;

std::vector<ContactRow> rows_of(const std::vector<Contact> &contacts) {
    std::vector<ContactRow> rows;
    for (const Contact &c : contacts)
        rows.emplace_back(c.link, c.shape, c.center[0], c.center[1], c.center[2], c.size, c.cell_class, c.probability,
                          c.depth);
    std::sort(rows.begin(), rows.end());
    return rows;
}

using CostRow = std::tuple<uint32_t, int, uint16_t, uint16_t, uint16_t, int, double, double>;

// Every cost box of the last query (none dropped), as the C shim builds them.
std::vector<CostRow> cost_rows(const LinkSet &links, CostCollector &cost, double &total) {
    std::vector<Aabb> boxes_of_links;
    link_boxes(links, cost, boxes_of_links);
    std::vector<CostBox> boxes;
    total = cost.finish(boxes_of_links, UINT32_MAX, boxes).total;
    std::vector<CostRow> rows;
    for (const CostBox &b : boxes)
        rows.emplace_back(b.link, b.cell.depth, b.cell.key[0], b.cell.key[1], b.cell.key[2], b.cell_class,
                          b.probability, b.cost);
    std::sort(rows.begin(), rows.end());
    return rows;
}

class AmortizedParity : public ::testing::Test {
protected:
    std::unique_ptr<SensorOctree> tree = mixed_octree(7);
    LinkSet links = make_robot();
    std::mt19937_64 rng{11};
    AmortizedEngine amortized;
    DirectEngine direct;
    std::vector<Contact> a_contacts, d_contacts;

    // Both engines on one collision query: the same answer, the same
    // contacts (depths too: the same pair, the same kernel).
    void expect_same_contacts(const CollisionSettings &s, int trial) {
        const CollisionOutcome a = amortized.collide(*tree, links, s, a_contacts);
        const CollisionOutcome d = direct.collide(*tree, links, s, d_contacts);
        ASSERT_EQ(a.collided, d.collided) << trial;
        ASSERT_EQ(rows_of(a_contacts), rows_of(d_contacts)) << trial;
    }
};

TEST_F(AmortizedParity, MapHasEveryKindOfCell) {
    const TreeStats stats = tree->stats();
    EXPECT_GT(stats.leaves[kOccupied], 100u);
    EXPECT_GT(stats.leaves[kUncertain], 100u);
    EXPECT_GT(stats.leaves[kFree], 1000u);
}

// Leaves and unknown cubes cover the map cube exactly once: their volumes
// (in finest cells) add up to the cube's, and none overlaps another.
TEST_F(AmortizedParity, UnknownCubesTileTheMapCubeWithTheLeaves) {
    const OctreeView view = tree->view();
    CellBoxes unknown;
    extract_unknown_boxes(view, unknown);
    ASSERT_GT(unknown.size(), 100u);
    auto volume = [](const CellKey &k) { return static_cast<uint64_t>(k.width_in_cells()) * k.width_in_cells() * k.width_in_cells(); };
    uint64_t cells = 0;
    for (const CellKey &k : unknown.keys) cells += volume(k);
    for_each_leaf(view, [&](OctreeView::NodeRef, const CellKey &k) { cells += volume(k); });
    EXPECT_EQ(cells, uint64_t{1} << (3 * kTreeDepth));
    for (size_t i = 0; i < unknown.size(); ++i) {
        const Vec3 center = unknown.boxes[i].center();
        ASSERT_EQ(tree->classify(center).cell_class, kUnknown) << i;
        ASSERT_EQ(unknown.boxes[i].lo, cell_box(unknown.keys[i], view.resolution()).lo);
    }
    // An empty map is one unknown cube, the map cube.
    const SensorOctree empty{OctreeParams()};
    extract_unknown_boxes(empty.view(), unknown);
    ASSERT_EQ(unknown.size(), 1u);
    EXPECT_EQ(unknown.keys[0].depth, 0);
}

// Every cube the engines cut from the root (child_cell at the parents'
// mid-planes), known or unknown, equals cell_box of its key bit for bit:
// the boxes the amortized engine extracts are the direct engine's.
void expect_cut_boxes_equal_key_boxes(const OctreeView &view, const OctreeCell &cell, uint64_t &checked) {
    const Aabb from_key = cell_box(cell.key, view.resolution());
    ASSERT_EQ(cell.box.lo, from_key.lo);
    ASSERT_EQ(cell.box.hi, from_key.hi);
    ++checked;
    if (cell.node == nullptr || !view.has_children(cell.node)) return;
    const Vec3 mid = mid_planes(cell, view.resolution());
    for (int i = 0; i < 8; ++i)
        expect_cut_boxes_equal_key_boxes(view, child_cell(cell, view.child(cell.node, i), i, mid), checked);
}

TEST_F(AmortizedParity, KeyBoxesEqualTheCutBoxes) {
    const OctreeView view = tree->view();
    uint64_t checked = 0;
    expect_cut_boxes_equal_key_boxes(view, root_cell(view), checked);
    EXPECT_GT(checked, 10000u);
}

TEST_F(AmortizedParity, CostEqualsTheDirectEngines) {
    int with_cost = 0;
    for (int unknown_occupied = 0; unknown_occupied < 2; ++unknown_occupied) {
        const CollisionSettings s = cost_settings(*tree, unknown_occupied != 0);
        for (int trial = 0; trial < 150; ++trial) {
            random_poses(links, rng);
            ASSERT_NO_FATAL_FAILURE(expect_same_contacts(s, trial));
            double a_total = 0.0, d_total = 0.0;
            const std::vector<CostRow> a_rows = cost_rows(links, amortized.cost(), a_total);
            const std::vector<CostRow> d_rows = cost_rows(links, direct.cost(), d_total);
            ASSERT_EQ(a_rows, d_rows) << trial;
            ASSERT_NEAR(a_total, d_total, 1e-12 * std::max(1.0, d_total)) << trial;
            with_cost += a_rows.empty() ? 0 : 1;
        }
    }
    EXPECT_GT(with_cost, 100);  // the poses do reach uncertain and unknown space
}

TEST_F(AmortizedParity, UnknownOccupiedEqualsTheDirectEngines) {
    CollisionSettings s = cost_settings(*tree, true);
    s.cost = false;
    const DistanceSettings ds = distance_settings(*tree, true, false);
    int unknown_contacts = 0;
    std::vector<double> a_links, d_links;
    for (int trial = 0; trial < 200; ++trial) {
        random_poses(links, rng);
        ASSERT_NO_FATAL_FAILURE(expect_same_contacts(s, trial));
        for (const Contact &c : a_contacts) unknown_contacts += c.cell_class == kUnknown ? 1 : 0;
        const DistanceOutcome ad = amortized.distance(*tree, links, ds, &a_links);
        const DistanceOutcome dd = direct.distance(*tree, links, ds, &d_links);
        ASSERT_EQ(ad.found, dd.found);
        ASSERT_NEAR(ad.distance, dd.distance, 1e-12) << trial;
        ASSERT_EQ(a_links, d_links) << trial;
    }
    EXPECT_GT(unknown_contacts, 100);
}

TEST_F(AmortizedParity, PenetrationAndSignedDistanceEqualTheDirectEngines) {
    int deep = 0;
    for (int unknown_occupied = 0; unknown_occupied < 2; ++unknown_occupied) {
        CollisionSettings s = cost_settings(*tree, unknown_occupied != 0);
        s.cost = false, s.penetration = true;
        const DistanceSettings ds = distance_settings(*tree, unknown_occupied != 0, true);
        for (int trial = 0; trial < 150; ++trial) {
            random_poses(links, rng);
            ASSERT_NO_FATAL_FAILURE(expect_same_contacts(s, trial));
            const DistanceOutcome ad = amortized.distance(*tree, links, ds, nullptr);
            const DistanceOutcome dd = direct.distance(*tree, links, ds, nullptr);
            ASSERT_EQ(ad.found, dd.found);
            ASSERT_NEAR(ad.distance, dd.distance, 1e-12) << trial;  // ties may differ in the last bit
            ASSERT_EQ(ad.cell_unknown, dd.cell_unknown) << trial;
            deep += ad.distance < -0.01 ? 1 : 0;
        }
    }
    EXPECT_GT(deep, 50);
}

// Plain queries build the obstacle tree only; the first cost query adds the
// uncertain and unknown trees, later ones (other poses, unknown occupied)
// reuse them; a changed map rebuilds only what the next query needs.
TEST_F(AmortizedParity, TreesAreBuiltOncePerFrameOnFirstNeed) {
    const CollisionSettings cost = cost_settings(*tree, false);
    CollisionSettings plain = cost;
    plain.cost = false;
    random_poses(links, rng);
    amortized.collide(*tree, links, plain, a_contacts);
    amortized.distance(*tree, links, distance_settings(*tree, false, true), nullptr);
    EXPECT_EQ(amortized.stats().builds, 1u);
    const uint64_t obstacle_boxes = amortized.stats().boxes;
    EXPECT_EQ(obstacle_boxes, tree->stats().leaves[kOccupied]);

    amortized.collide(*tree, links, cost, a_contacts);
    EXPECT_EQ(amortized.stats().builds, 3u);
    for (int trial = 0; trial < 5; ++trial) {
        random_poses(links, rng);
        amortized.collide(*tree, links, cost, a_contacts);
        amortized.collide(*tree, links, cost_settings(*tree, true), a_contacts);
        amortized.distance(*tree, links, distance_settings(*tree, true, false), nullptr);
    }
    EXPECT_EQ(amortized.stats().builds, 3u);
    EXPECT_EQ(amortized.stats().boxes, obstacle_boxes);  // stats count obstacle boxes only

    std::vector<double> xyz{0.5, 0.5, 1.0};
    tree->insert(PointSource{reinterpret_cast<const unsigned char *>(xyz.data()), 1, 3 * sizeof(double), true},
                 InsertSettings());
    amortized.collide(*tree, links, plain, a_contacts);
    EXPECT_EQ(amortized.stats().builds, 4u);
    amortized.collide(*tree, links, cost, a_contacts);
    EXPECT_EQ(amortized.stats().builds, 6u);
}

}  // namespace
