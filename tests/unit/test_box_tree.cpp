// The amortized broad-phase tree (paper IV.A): valid after the linear build
// and after every refinement step, overlap and nearest queries equal to
// brute force in every state, no allocation on the query and refine paths,
// and the quality curve (SAH relative to the median-split AabbTree) on the
// paper's synthetic scene and on the geb079 map.
#include "broadphase/box_tree.hpp"

#include "alloc_counter.hpp"
#include "box_tree_checks.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

using octoprox::Aabb;
using octoprox::BoxTree;
using octoprox::BoxTreeOptions;
using octoprox::Vec3;

namespace {

// Set when a test skipped for want of the shared data: main() exits 77.
bool g_data_missing = false;

// The quality target of the issue and the refinement budget documented for
// it: a path per query for the first 256 queries of a frame.
constexpr double kTargetRatio = 1.10;
constexpr uint64_t kTargetSteps = 256;

Aabb bounds_of(const std::vector<Aabb> &boxes) {
    Aabb all;
    for (const Aabb &b : boxes) all.grow(b);
    return all;
}

void expect_queries_match(const BoxTree &tree, const std::vector<Aabb> &boxes,
                          const std::vector<Aabb> &queries, const std::string &state) {
    ASSERT_EQ(unit::check_tree(tree, boxes), "") << state;
    for (const Aabb &q : queries) {
        ASSERT_EQ(unit::tree_overlaps(tree, q), unit::brute_overlaps(boxes, q)) << state;
        ASSERT_EQ(unit::tree_nearest(tree, q), unit::brute_nearest(boxes, q)) << state;
    }
}

std::vector<Aabb> query_mix(const std::vector<Aabb> &boxes, size_t n, std::mt19937_64 &rng) {
    Aabb region = bounds_of(boxes);
    const double size = region.longest_edge();
    region.inflate(0.1 * size);  // some queries outside everything
    std::vector<Aabb> queries = unit::random_queries(n / 2, region, 0.0, 0.02 * size, rng);
    const std::vector<Aabb> large = unit::random_queries(n - n / 2, region, 0.02 * size, 0.3 * size, rng);
    queries.insert(queries.end(), large.begin(), large.end());
    return queries;
}

// Builds and checks a tree over `boxes`, then refines it and checks again.
void expect_valid_through_refinement(const std::vector<Aabb> &boxes, const BoxTreeOptions &options,
                                     const std::string &what) {
    std::mt19937_64 rng(boxes.size());
    const std::vector<Aabb> queries = query_mix(boxes, 40, rng);
    BoxTree tree;
    tree.build(boxes, options);
    expect_queries_match(tree, boxes, queries, what + ", built");
    tree.refine(500);
    expect_queries_match(tree, boxes, queries, what + ", refined 500 steps");
}

}  // namespace

TEST(BoxTree, EmptyAndTinySets) {
    BoxTree tree;
    tree.build(std::vector<Aabb>());
    EXPECT_TRUE(tree.empty());
    EXPECT_EQ(tree.refine(10), 0u);
    EXPECT_TRUE(tree.for_each_overlap(Aabb{Vec3::Zero(), Vec3::Ones()}, [](int32_t) { return false; }));
    std::mt19937_64 rng(11);
    for (size_t n = 1; n <= 6; ++n)
        expect_valid_through_refinement(unit::random_boxes(n, 1.0, 0.5, rng), BoxTreeOptions(),
                                        std::to_string(n) + " boxes");
}

TEST(BoxTree, DegenerateSets) {
    std::mt19937_64 rng(12);
    // All boxes equal: every code equal, the positions split the run in halves.
    const std::vector<Aabb> same(1000, Aabb{Vec3(1, 2, 3), Vec3(2, 3, 4)});
    BoxTree tree;
    tree.build(same);
    EXPECT_LE(tree.height(), 11) << "a run of equal codes splits in halves";
    expect_valid_through_refinement(same, BoxTreeOptions(), "all equal");
    // Flat (all centres on a plane) and collinear sets.
    std::vector<Aabb> flat = unit::random_boxes(2000, 10.0, 1.0, rng), line = flat;
    for (Aabb &b : flat) b = Aabb::from_center(Vec3(b.center().x(), b.center().y(), 0.0), b.half_extent());
    for (Aabb &b : line) b = Aabb::from_center(Vec3(b.center().x(), 0.0, 0.0), b.half_extent());
    expect_valid_through_refinement(flat, BoxTreeOptions(), "flat");
    expect_valid_through_refinement(line, BoxTreeOptions(), "collinear");
    // Points (zero-size boxes) and boxes of wildly different sizes.
    std::vector<Aabb> points = unit::random_boxes(2000, 10.0, 1.0, rng);
    for (Aabb &b : points) b = Aabb{b.center(), b.center()};
    expect_valid_through_refinement(points, BoxTreeOptions(), "points");
    std::vector<Aabb> mixed = unit::random_boxes(2000, 10.0, 0.01, rng);
    for (size_t i = 0; i < mixed.size(); i += 50) mixed[i].inflate(5.0);
    expect_valid_through_refinement(mixed, BoxTreeOptions(), "mixed sizes");
}

// Nested boxes sharing a corner: the lowest-area tree is a chain (the
// smallest boxes paired first), so rotations push the height up; a depth
// cap must stop them there, and the tree must stay valid.
TEST(BoxTree, RotationsRespectTheDepthCap) {
    std::vector<Aabb> nested;
    for (int i = 0; i < 400; ++i) nested.push_back(Aabb{Vec3::Zero(), Vec3::Constant(std::pow(1.15, i))});
    std::mt19937_64 rng(22);
    const std::vector<Aabb> queries = query_mix(nested, 100, rng);
    for (int cap : {BoxTree::kMaxDepth, 24}) {
        BoxTreeOptions options;
        options.max_depth = cap;
        BoxTree tree;
        tree.build(nested, options);
        const int built_height = tree.height();
        const double built_cost = tree.sah_cost();
        tree.refine(200000);
        std::printf("nested boxes, depth cap %d: height %d -> %d, SAH %.3f -> %.3f\n", cap, built_height,
                    tree.height(), built_cost, tree.sah_cost());
        EXPECT_GT(tree.height(), built_height);
        EXPECT_LE(tree.height(), cap);
        EXPECT_LT(tree.sah_cost(), built_cost);
        expect_queries_match(tree, nested, queries, "nested, cap " + std::to_string(cap));
    }
}

TEST(BoxTree, EveryLatticeAndDigitSizeBuildsValidTrees) {
    std::mt19937_64 rng(13);
    const std::vector<Aabb> boxes = unit::random_boxes(3000, 20.0, 0.5, rng);
    for (int bits : {1, 2, 5, 10, 16, 21})
        for (int digit_bits : {8, 11}) {
            BoxTreeOptions options;
            options.morton_bits = bits;
            options.digit_bits = digit_bits;
            expect_valid_through_refinement(boxes, options,
                                            "bits " + std::to_string(bits) + ", digit " + std::to_string(digit_bits));
        }
}

// Every state answers exactly like brute force: after the build, after 1,
// 10 and 1,000 refinement steps (and 20,000, past convergence here).
TEST(BoxTree, QueriesMatchBruteForceWhileRefining) {
    std::mt19937_64 rng(14);
    std::vector<Aabb> boxes = unit::random_boxes(6000, 20.0, 1.5, rng);
    const std::vector<Aabb> queries = query_mix(boxes, 400, rng);
    BoxTree tree;
    tree.build(boxes);
    uint64_t done = 0;
    for (uint64_t steps : {0, 1, 10, 1000, 20000}) {
        tree.refine(static_cast<uint32_t>(steps - done));
        done = steps;
        expect_queries_match(tree, boxes, queries, std::to_string(steps) + " steps");
    }
    // A visitor returning false stops the traversal at the first leaf.
    int visited = 0;
    EXPECT_FALSE(tree.for_each_overlap(bounds_of(boxes), [&](int32_t) { return ++visited, false; }));
    EXPECT_EQ(visited, 1);
    // A negative bound stops the nearest-first search.
    visited = 0;
    tree.for_each_by_distance(queries[0], std::numeric_limits<double>::infinity(),
                              [&](int32_t, double) { return ++visited, -1.0; });
    EXPECT_EQ(visited, 1);
}

TEST(BoxTree, WarmRebuildRefineAndQueriesDoNotAllocate) {
    std::mt19937_64 rng(15);
    const std::vector<Aabb> boxes = unit::random_boxes(5000, 20.0, 1.0, rng);
    const std::vector<Aabb> queries = query_mix(boxes, 50, rng);
    BoxTree tree;
    tree.build(boxes);  // warms every buffer
    const uint64_t before = unit::allocation_count();
    tree.build(boxes);
    tree.build(boxes.data(), boxes.size() / 2);
    tree.refine(1000);
    size_t hits = 0;
    double nearest = 0.0;
    for (const Aabb &q : queries) {
        tree.for_each_overlap(q, [&](int32_t) { ++hits; });
        nearest += tree.for_each_by_distance(q, 1e300, [](int32_t, double d) { return d; });
    }
    EXPECT_EQ(unit::allocation_count(), before) << hits << " " << nearest;
}

// The Morton build is O(n): printed for doubling sizes (not asserted, the
// machine is shared).
namespace {

struct CurvePoint {
    uint64_t steps;
    double ratio, inner_ratio;
};

// Refines in doubling chunks up to max_steps, recording the ratio after
// 0, 1, 2, 4, ... steps (and at kTargetSteps).
std::vector<CurvePoint> quality_curve(BoxTree &tree, uint64_t max_steps) {
    const octoprox::SahCost reference = tree.reference_sah();
    std::vector<CurvePoint> curve;
    uint64_t done = 0;
    for (uint64_t next = 0;; next = next == 0 ? 1 : 2 * next) {
        tree.refine(static_cast<uint32_t>(next - done));
        done = next;
        const octoprox::SahCost cost = tree.sah();
        curve.push_back({done, cost.total() / reference.total(), cost.inner / reference.inner});
        if (done >= max_steps) return curve;
    }
}

uint64_t first_steps_within(const std::vector<CurvePoint> &curve, double target) {
    for (const CurvePoint &p : curve)
        if (p.ratio <= target) return p.steps;
    return std::numeric_limits<uint64_t>::max();
}

void print_build_times(const char *label, const std::vector<Aabb> &boxes) {
    BoxTree tree;
    std::printf("%s, %zu boxes: warm builds (best of 10)\n", label, boxes.size());
    for (int bits : {10, 21})
        for (int digit_bits : {8, 11}) {
            BoxTreeOptions options;
            options.morton_bits = bits;
            options.digit_bits = digit_bits;
            tree.build(boxes, options);
            const double ms = unit::best_milliseconds(10, [&] { tree.build(boxes, options); });
            std::printf("  Morton tree, %2d bits/axis, %2d-bit digits: %7.3f ms\n", bits, digit_bits, ms);
        }
    octoprox::AabbTree median;
    std::printf("  median-split AabbTree:                   %7.3f ms\n",
                unit::best_milliseconds(10, [&] { median.build(boxes); }));
}

// The measured side of the SAH: nodes tested by link-sized overlap queries.
void print_nodes_tested(const std::vector<Aabb> &boxes, BoxTree &fresh, BoxTree &refined,
                        BoxTree &converged, uint64_t converged_steps) {
    std::mt19937_64 rng(17);
    const std::vector<Aabb> queries = unit::random_queries(2000, bounds_of(boxes), 0.1, 0.6, rng);
    octoprox::AabbTree median;
    median.build(boxes);
    std::printf("  nodes tested by 2,000 overlap queries (cubes 0.1-0.6 m): Morton %llu, after %llu steps %llu, "
                "after %llu steps %llu; median split %llu\n",
                (unsigned long long)unit::nodes_tested(fresh, queries), (unsigned long long)kTargetSteps,
                (unsigned long long)unit::nodes_tested(refined, queries), (unsigned long long)converged_steps,
                (unsigned long long)unit::nodes_tested(converged, queries),
                (unsigned long long)unit::nodes_tested(median, queries));
}

// Builds the tree over the scene's cells, prints and checks its quality
// curve, and checks the final states against brute force.
void check_scene_quality(const char *label, const std::vector<Aabb> &boxes, uint64_t curve_steps) {
    print_build_times(label, boxes);
    BoxTree fresh, tree;
    fresh.build(boxes);
    tree.build(boxes);
    BoxTree refined = fresh;
    const double refine_ms = unit::best_milliseconds(1, [&] { refined.refine(kTargetSteps); });
    const std::vector<CurvePoint> curve = quality_curve(tree, curve_steps);
    const octoprox::SahCost reference = tree.reference_sah();
    const octoprox::SahCost binned = unit::binned_sah_cost(boxes);
    std::printf("  SAH of the median-split tree: %.3f (inner %.3f + leaves %.3f); height %d -> %d\n",
                reference.total(), reference.inner, reference.leaves, fresh.height(), tree.height());
    std::printf("  (for scale: a binned-SAH top-down tree has %.3f, ratio %.4f)\n", binned.total(),
                binned.total() / reference.total());
    std::printf("  refinement: %llu steps in %.3f ms (%.2f us/step)\n", (unsigned long long)kTargetSteps,
                refine_ms, 1e3 * refine_ms / double(kTargetSteps));
    std::printf("  steps -> SAH ratio (total, inner nodes only)\n");
    for (const CurvePoint &p : curve)
        std::printf("  %9llu  %.4f  %.4f\n", (unsigned long long)p.steps, p.ratio, p.inner_ratio);
    for (size_t i = 1; i < curve.size(); ++i)
        EXPECT_LE(curve[i].ratio, curve[i - 1].ratio * (1.0 + 1e-9)) << "the SAH rose at " << curve[i].steps;
    const uint64_t first = first_steps_within(curve, kTargetRatio);
    std::printf("  ratio <= %.2f first after %llu steps (target: within %llu)\n", kTargetRatio,
                (unsigned long long)first, (unsigned long long)kTargetSteps);
    EXPECT_LE(refined.sah_ratio(), kTargetRatio) << "after " << kTargetSteps << " steps";
    print_nodes_tested(boxes, fresh, refined, tree, curve.back().steps);
    std::mt19937_64 rng(18);
    const std::vector<Aabb> queries = query_mix(boxes, 100, rng);
    expect_queries_match(refined, boxes, queries, std::string(label) + ", refined");
    expect_queries_match(tree, boxes, queries, std::string(label) + ", converged");
}

}  // namespace

// Paper section V: 7,784 random cells of 0.2 m in [-20, 20]^3.
TEST(BoxTree, SyntheticSceneQuality) {
    const auto octree = unit::synthetic_octree(19);
    const octoprox::CellBoxes cells = unit::occupied_cells(*octree);
    ASSERT_EQ(cells.size(), 7784u);
    check_scene_quality("synthetic scene", cells.boxes, 8 * cells.size());
}

TEST(BoxTree, Geb079Quality) {
    const std::string path = unit::data_dir() + "/maps/geb079.bt";
    if (!unit::file_exists(path)) {
        g_data_missing = true;
        UNIT_SKIP_WITHOUT_DATA(path + " not found, set OPX_DATA_DIR to the shared data folder");
    }
    const auto octree = unit::read_octree(path);
    octoprox::CellBoxes cells;
    const double extract_ms = unit::best_milliseconds(3, [&] { cells = unit::occupied_cells(*octree); });
    ASSERT_EQ(cells.size(), 143729u);
    std::printf("geb079: extracting %zu occupied cells (T_1,1): %.2f ms\n", cells.size(), extract_ms);
    check_scene_quality("geb079", cells.boxes, 4 * cells.size());
}

int main(int argc, char **argv) {
    testing::InitGoogleTest(&argc, argv);
    const int failed = RUN_ALL_TESTS();
    if (failed == 0 && g_data_missing) {
        std::printf("SKIP: the shared data is absent (see above)\n");
        return 77;
    }
    return failed;
}
