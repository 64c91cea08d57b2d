// ingest_exact: a ray-cast insert gives OctoMap's map bit for bit.  Every
// frame goes into an OctoProx map and into an OctoMap OcTree
// (insertPointCloud, not discretized, lazy evaluation off); after each, the
// two maps must hold the same cells with the same float log-odds and the
// same leaves (the same pruning), and the insert report must count the
// cells OctoMap's computeUpdate finds.  The scenes: random clouds with far
// points and points outside the map, a room seen by a depth camera, ties
// (cell faces, edges, corners, rays along the axes and diagonals), dense
// rows of points on planes (many rays a cell), several
// frames into one map until it clamps and prunes, cut rays (max range),
// maps loaded from .bt and .ot, and every thread count.
#include "ingest_scenes.hpp"
#include "real_support.hpp"

#include <cstring>
#include <sstream>
#include <string>

namespace {

using ingest::Frame;

// The frame in the sensor frame (map point - origin, exact in double), with
// the sensor at the origin: the library's transform gives the map points
// back exactly.
opx_insert_report insert_ours(opx_octree *tree, const Frame &frame, double max_range, uint32_t threads) {
    std::vector<double> xyz;
    for (const octomap::point3d &p : frame.points)
        for (int a = 0; a < 3; ++a) xyz.push_back(double{p(a)} - double{frame.origin(a)});
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    for (int a = 0; a < 3; ++a) options.sensor_pose.position[a] = frame.origin(a);
    options.max_range = max_range;
    options.max_threads = threads;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    real::check_ok(opx_octree_insert_points(tree, xyz.data(), frame.points.size(), 0, OPX_SCALAR_FLOAT64, &options,
                                            &report),
                   "opx_octree_insert_points");
    return report;
}

void insert_theirs(octomap::OcTree &tree, const Frame &frame, double max_range, size_t &hits, size_t &misses) {
    octomap::Pointcloud cloud;
    for (const octomap::point3d &p : frame.points) cloud.push_back(p);
    const double range = max_range > 0 ? max_range : -1.0;
    octomap::KeySet free_cells, occupied_cells;
    tree.computeUpdate(cloud, frame.origin, free_cells, occupied_cells, range);
    hits = occupied_cells.size();
    misses = free_cells.size();
    tree.insertPointCloud(cloud, frame.origin, range, false, false);
}

bool same_leaves(const std::vector<real::LeafKey> &a, const std::vector<real::LeafKey> &b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].depth != b[i].depth || a[i].min_key != b[i].min_key ||
            std::memcmp(&a[i].log_odds, &b[i].log_odds, sizeof(float)) != 0)
            return false;
    return true;
}

void assert_same(const char *label, const opx_octree *ours, const octomap::OcTree &theirs) {
    const real::CellComparison c = real::compare_cells(real::expand_octoprox(ours), real::expand_octomap(theirs));
    if (!c.identical()) real::print_comparison(label, c);
    assert_true(c.identical());
    const bool same = same_leaves(real::leaf_keys_octoprox(ours), real::leaf_keys_octomap(theirs));
    if (!same) print_message("%s: the same cells, but other leaves (pruning differs)\n", label);
    assert_true(same);
}

// One frame into both maps, then the comparison.
void insert_both(opx_octree *ours, octomap::OcTree &theirs, const Frame &frame, double max_range, uint32_t threads,
                 const std::string &label) {
    const opx_insert_report report = insert_ours(ours, frame, max_range, threads);
    size_t hits = 0, misses = 0;
    insert_theirs(theirs, frame, max_range, hits, misses);
    assert_int_equal(report.cells_hit, hits);
    assert_int_equal(report.cells_missed, misses);
    assert_int_equal(report.points_used + report.points_nonfinite + report.points_out_of_range +
                         report.points_outside_map,
                     frame.points.size());
    assert_same(label.c_str(), ours, theirs);
}

void test_random_frames(void **) {
    std::mt19937 rng(20261124);
    for (const double resolution : {0.05, 0.1, 0.02}) {
        opx_octree *ours = real::new_octree(resolution);
        octomap::OcTree theirs(resolution);
        for (int i = 0; i < 6; ++i) {
            const double max_range = i % 3 == 2 ? 1.5 : -1.0;  // every third frame cut at 1.5 m
            const Frame frame = ingest::random_frame(rng, 2.0f, 3000, i % 2 == 1);
            insert_both(ours, theirs, frame, max_range, 1 + i % 3, "random frame " + std::to_string(i));
        }
        opx_octree_destroy(ours);
    }
}

// The same frame over and over clamps the cells and prunes the free space;
// new frames then open pruned nodes again.
void test_clamped_and_pruned(void **) {
    std::mt19937 rng(7);
    const double resolution = 0.1;
    opx_octree *ours = real::new_octree(resolution);
    octomap::OcTree theirs(resolution);
    const Frame same = ingest::random_frame(rng, 1.0f, 800, false);
    for (int i = 0; i < 14; ++i) insert_both(ours, theirs, same, -1.0, 2, "repeated frame " + std::to_string(i));
    for (int i = 0; i < 4; ++i)
        insert_both(ours, theirs, ingest::random_frame(rng, 1.2f, 800, false), -1.0, 1,
                    "after clamping " + std::to_string(i));
    opx_octree_destroy(ours);
}

void test_ties(void **) {
    for (const double resolution : {0.125, 0.25, 0.1, 0.05}) {
        opx_octree *ours = real::new_octree(resolution);
        octomap::OcTree theirs(resolution);
        for (int variant = 0; variant < 6; ++variant) {
            const double max_range = variant >= 3 ? 6.5 * resolution : -1.0;
            insert_both(ours, theirs, ingest::tie_frame(resolution, variant), max_range, 1,
                        "ties " + std::to_string(resolution) + " variant " + std::to_string(variant));
        }
        opx_octree_destroy(ours);
    }
}

void test_dense_rows(void **) {
    for (const double resolution : {0.1, 0.05}) {
        opx_octree *ours = real::new_octree(resolution);
        octomap::OcTree theirs(resolution);
        for (int variant = 0; variant < 4; ++variant) {
            const double max_range = variant == 3 ? 8.5 * resolution : -1.0;
            const std::string label =
                "dense rows " + std::to_string(resolution) + " variant " + std::to_string(variant);
            insert_both(ours, theirs, ingest::dense_frame(resolution, variant), max_range, 1 + variant % 2, label);
        }
        opx_octree_destroy(ours);
    }
}

void test_room(void **) {
    for (const double resolution : {0.1, 0.05}) {
        opx_octree *ours = real::new_octree(resolution);
        octomap::OcTree theirs(resolution);
        insert_both(ours, theirs, ingest::room_frame(octomap::point3d(-1.0f, 0.2f, 1.2f), 0.1f), -1.0, 2,
                    "room, first frame");
        insert_both(ours, theirs, ingest::room_frame(octomap::point3d(-0.8f, 0.1f, 1.2f), 0.6f), 4.0, 1,
                    "room, second frame cut at 4 m");
        opx_octree_destroy(ours);
    }
}

// Rays along the map's outer faces (its last cells, at +-32768 cells),
// where a step may leave the key range.
void test_map_edge(void **) {
    const double resolution = 0.25;
    const float edge = static_cast<float>(32768 * resolution);
    opx_octree *ours = real::new_octree(resolution);
    octomap::OcTree theirs(resolution);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> near(-3.0f, 0.0f), across(-2.0f, 2.0f);
    for (const float sign : {1.0f, -1.0f}) {
        Frame frame;
        frame.origin = octomap::point3d(sign * (edge - 1.1f), 0.3f, -0.2f);
        for (int i = 0; i < 400; ++i)
            frame.points.emplace_back(sign * (edge + near(rng) * (i % 2 ? 1.0f : 0.02f)), across(rng), across(rng));
        frame.points.emplace_back(sign * edge, 0.0f, 0.0f);  // just outside on the positive side
        insert_both(ours, theirs, frame, -1.0, 2, sign > 0 ? "upper map edge" : "lower map edge");
    }
    opx_octree_destroy(ours);
}

// Points hundreds of metres apart at 2 cm: the rays span more cells than
// the per-frame bitmaps cover, and the insert takes OctoMap's way.
void test_far_points(void **) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> across(-600.0f, 600.0f);
    Frame frame;
    frame.origin = octomap::point3d(0.1f, 0.2f, 0.3f);
    for (int i = 0; i < 60; ++i) frame.points.emplace_back(across(rng), across(rng), across(rng) * 0.1f);
    for (int i = 0; i < 200; ++i) frame.points.emplace_back(across(rng) * 0.002f, across(rng) * 0.002f, 1.0f);
    opx_octree *ours = real::new_octree(0.02);
    octomap::OcTree theirs(0.02);
    insert_both(ours, theirs, frame, -1.0, 2, "far points");
    insert_both(ours, theirs, frame, 100.0, 1, "far points cut at 100 m");
    opx_octree_destroy(ours);
}

// OctoMap writes a map, OctoProx loads it, and both take the next frame.
void check_loaded(bool binary) {
    std::mt19937 rng(99);
    const double resolution = 0.1;
    octomap::OcTree theirs(resolution);
    size_t hits = 0, misses = 0;
    for (int i = 0; i < 5; ++i) insert_theirs(theirs, ingest::random_frame(rng, 1.5f, 1500, false), -1.0, hits, misses);
    std::stringstream bytes;
    if (binary) assert_true(theirs.writeBinary(bytes));  // max-likelihood and pruned, as OctoMap saves
    else assert_true(theirs.write(bytes));
    const std::string data = bytes.str();
    opx_octree *ours = nullptr;
    real::check_ok(opx_octree_load_memory(data.data(), data.size(), nullptr, &ours), "opx_octree_load_memory");
    assert_same(binary ? "loaded .bt" : "loaded .ot", ours, theirs);
    for (int i = 0; i < 3; ++i)
        insert_both(ours, theirs, ingest::random_frame(rng, 1.5f, 1500, false), -1.0, 2,
                    std::string(binary ? ".bt" : ".ot") + " then frame " + std::to_string(i));
    opx_octree_destroy(ours);
}
void test_loaded_bt(void **) { check_loaded(true); }
void test_loaded_ot(void **) { check_loaded(false); }

// The map does not depend on how many threads the insert used.
void test_thread_counts(void **) {
    std::mt19937 rng(5);
    const Frame frame = ingest::room_frame(octomap::point3d(0.5f, -0.5f, 1.0f), 2.0f);
    const Frame second = ingest::random_frame(rng, 2.5f, 20000, true);
    std::vector<real::LeafKey> first_leaves;
    for (const uint32_t threads : {1u, 2u, 3u, 8u, 0u}) {
        opx_octree *ours = real::new_octree(0.05);
        insert_ours(ours, frame, -1.0, threads);
        insert_ours(ours, second, 3.0, threads);
        const std::vector<real::LeafKey> leaves = real::leaf_keys_octoprox(ours);
        if (threads == 1) first_leaves = leaves;
        else assert_true(same_leaves(leaves, first_leaves));
        opx_octree_destroy(ours);
    }
}

}  // namespace

int main() {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_random_frames), cmocka_unit_test(test_clamped_and_pruned),
        cmocka_unit_test(test_ties),          cmocka_unit_test(test_dense_rows),
        cmocka_unit_test(test_room),
        cmocka_unit_test(test_loaded_bt),     cmocka_unit_test(test_loaded_ot),
        cmocka_unit_test(test_thread_counts), cmocka_unit_test(test_map_edge),
        cmocka_unit_test(test_far_points),
    };
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
