/*
 * Reading the map: opx_octree_classify, _get_stats and _get_leaves.  Most
 * tests use the map of one ray from (C0, C0, C0) to sensor-frame (1, 0, 0):
 * free cells centred at x = 0.125, 0.375, 0.625, 0.875 and an occupied
 * cell at x = 1.125 (y = z = C0), all at depth 16 (edge RES = 0.25).
 */
#include "opx_test.h"

static opx_octree *new_ray_map(void) {
    opx_octree *tree = new_tree(RES);
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    return tree;
}

static void assert_unknown_cube(const opx_cell_info *info, uint32_t depth, double size, double x,
                                double y, double z) {
    assert_int_equal(info->cell_class, OPX_CELL_UNKNOWN);
    assert_true(info->probability == 0.5);
    assert_int_equal(info->depth, depth);
    assert_near(info->size, size, OPX_GEOM_TOL);
    assert_center(info->center, x, y, z);
}

/* ---- classify ---------------------------------------------------------- */

static void classify_unknown_gives_the_largest_unobserved_cube(void **state) {
    (void)state;
    opx_octree *empty = new_tree(RES);
    opx_cell_info info = classify_at(empty, 1.0, 2.0, 3.0);
    assert_unknown_cube(&info, 0, 65536 * RES, 0.0, 0.0, 0.0); /* the root cube */
    opx_octree_destroy(empty);

    opx_octree *tree = new_ray_map();
    info = classify_at(tree, C0, 0.375, C0); /* beside the ray: a finest cell */
    assert_unknown_cube(&info, 16, RES, C0, 0.375, C0);
    /* Key offset 400 differs from the map's at bit 8: a depth-8 cube of
     * 256 cells, [64, 128) m on each axis. */
    info = classify_at(tree, 100.0, 100.0, 100.0);
    assert_unknown_cube(&info, 8, 64.0, 96.0, 96.0, 96.0);
    /* Another octant of the root: a depth-1 cube. */
    info = classify_at(tree, -100.0, 5.0, 5.0);
    assert_unknown_cube(&info, 1, 8192.0, -4096.0, 4096.0, 4096.0);
    opx_octree_destroy(tree);
}

/* The cube is [-32768 * RES, 32768 * RES) = [-8192, 8192) m per axis. */
static void classify_at_the_edges_of_the_cube(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    map_snapshot before = take_snapshot(tree);
    const double inside[][3] = {{8191.9, 0, 0}, {-8192.0, 0, 0}, {0, 8191.99, -8192.0}};
    for (size_t i = 0; i < 3; ++i) {
        opx_cell_info info = OPX_CELL_INFO_INIT;
        assert_ok(opx_octree_classify(tree, inside[i], &info));
        assert_int_equal(info.cell_class, OPX_CELL_UNKNOWN);
    }
    const double outside[][3] = {{8192.0, 0, 0}, {-8192.01, 0, 0}, {0, 0, 1e30}, {0, -1e300, 0}};
    for (size_t i = 0; i < 4; ++i) {
        opx_cell_info info = OPX_CELL_INFO_INIT;
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_classify", "point",
                       opx_octree_classify(tree, outside[i], &info));
    }
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
}

static void classify_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    map_snapshot before = take_snapshot(tree);
    const char *fn = "opx_octree_classify";
    const double point[3] = {1.0, 0.0, 0.0};
    opx_cell_info info = OPX_CELL_INFO_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree", opx_octree_classify(NULL, point, &info));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "point", opx_octree_classify(tree, NULL, &info));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out", opx_octree_classify(tree, point, NULL));
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (int i = 0; i < 3; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            double p[3] = {1.0, 0.0, 0.0};
            p[axis] = bad[i];
            expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "point",
                           opx_octree_classify(tree, p, &info));
        }
    }
    info.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, fn, "struct_size", opx_octree_classify(tree, point, &info));
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
}

static void classify_writes_no_further_than_struct_size(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    const double point[3] = {1.125, C0, C0};
    opx_cell_info info;
    memset(&info, 0xAB, sizeof info);
    info.struct_size = (uint32_t)offsetof(opx_cell_info, center);
    assert_ok(opx_octree_classify(tree, point, &info));
    assert_int_equal(info.struct_size, offsetof(opx_cell_info, center));
    assert_int_equal(info.cell_class, OPX_CELL_OCCUPIED);
    assert_near(info.probability, 0.7, OPX_PROB_TOL);
    const unsigned char *bytes = (const unsigned char *)&info;
    for (size_t i = offsetof(opx_cell_info, center); i < sizeof info; ++i)
        assert_int_equal(bytes[i], 0xAB);
    opx_octree_destroy(tree);
}

/* ---- stats ------------------------------------------------------------- */

static void stats_of_an_empty_map_are_zero(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const opx_octree_stats s = stats_of(tree);
    assert_int_equal(s.struct_size, sizeof s);
    assert_int_equal(s.has_occupied, 0);
    assert_true(s.resolution == RES);
    assert_int_equal(s.leaves_occupied + s.leaves_uncertain + s.leaves_free + s.inner_nodes, 0);
    const double zero[3] = {0, 0, 0};
    assert_memory_equal(s.occupied_min, zero, sizeof zero);
    assert_memory_equal(s.occupied_max, zero, sizeof zero);
    assert_memory_equal(s.known_min, zero, sizeof zero);
    assert_memory_equal(s.known_max, zero, sizeof zero);
    opx_octree_destroy(tree);
}

/* Counts and tight bounds (cell boxes, not centres).  Inner nodes: the keys
 * x = 32768..32772 share their path down to depth 13 (14 nodes), split into
 * 2 nodes at depth 14 and 3 at depth 15: 19. */
static void stats_count_and_bound_the_cells(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    const opx_octree_stats s = stats_of(tree);
    assert_int_equal(s.leaves_occupied, 1);
    assert_int_equal(s.leaves_free, 4);
    assert_int_equal(s.leaves_uncertain, 0);
    assert_int_equal(s.inner_nodes, 19);
    assert_true(s.memory_bytes > 0);
    assert_int_equal(s.has_occupied, 1);
    assert_center(s.occupied_min, 1.0, 0.0, 0.0);
    assert_center(s.occupied_max, 1.25, RES, RES);
    assert_center(s.known_min, 0.0, 0.0, 0.0);
    assert_center(s.known_max, 1.25, RES, RES);
    opx_octree_destroy(tree);
}

static void stats_reject_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    opx_octree_stats s = OPX_OCTREE_STATS_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_get_stats", "tree",
                   opx_octree_get_stats(NULL, &s));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_get_stats", "out",
                   opx_octree_get_stats(tree, NULL));
    s.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_octree_get_stats", "struct_size",
                   opx_octree_get_stats(tree, &s));
    /* An older, smaller struct is written no further than its size. */
    memset(&s, 0xAB, sizeof s);
    s.struct_size = (uint32_t)offsetof(opx_octree_stats, inner_nodes);
    assert_ok(opx_octree_get_stats(tree, &s));
    assert_int_equal(s.leaves_free, 4);
    const unsigned char *bytes = (const unsigned char *)&s;
    for (size_t i = offsetof(opx_octree_stats, inner_nodes); i < sizeof s; ++i)
        assert_int_equal(bytes[i], 0xAB);
    opx_octree_destroy(tree);
}

/* ---- leaves ------------------------------------------------------------ */

static void leaves_come_depth_first_with_their_values(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    size_t count = 0;
    opx_leaf *leaves = all_leaves(tree, OPX_MASK_ALL_KNOWN, &count);
    assert_int_equal(count, 5);
    for (size_t i = 0; i < 5; ++i) {
        assert_center(leaves[i].center, C0 + (double)i * RES, C0, C0);
        assert_near(leaves[i].size, RES, OPX_GEOM_TOL);
        assert_int_equal(leaves[i].depth, 16);
        assert_int_equal(leaves[i].cell_class, i < 4 ? OPX_CELL_FREE : OPX_CELL_OCCUPIED);
        assert_near(leaves[i].probability, i < 4 ? 0.4 : 0.7, OPX_PROB_TOL);
    }
    free(leaves);
    opx_octree_destroy(tree);
}

static void leaves_are_filtered_by_class_mask(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    size_t count = 0;
    opx_leaf *leaves = all_leaves(tree, OPX_MASK_OCCUPIED, &count);
    assert_int_equal(count, 1);
    assert_near(leaves[0].center[0], 1.125, OPX_GEOM_TOL);
    free(leaves);
    leaves = all_leaves(tree, OPX_MASK_FREE, &count);
    assert_int_equal(count, 4);
    assert_int_equal(leaves[3].cell_class, OPX_CELL_FREE);
    free(leaves);
    leaves = all_leaves(tree, OPX_MASK_UNCERTAIN, &count);
    assert_int_equal(count, 0);
    free(leaves);
    leaves = all_leaves(tree, OPX_MASK_FREE | OPX_MASK_OCCUPIED, &count);
    assert_int_equal(count, 5);
    free(leaves);
    assert_ok(opx_octree_get_leaves(tree, 0u, NULL, 0, &count)); /* no class selected */
    assert_int_equal(count, 0);
    opx_octree_destroy(tree);
}

/* Too small: the first `capacity` leaves are written, nothing more, and
 * *out_count tells the size needed. */
static void leaves_buffer_too_small_reports_needed_count(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    size_t count = 0;
    opx_leaf *expected = all_leaves(tree, OPX_MASK_ALL_KNOWN, &count);
    opx_leaf buffer[8];
    memset(buffer, 0xAB, sizeof buffer);
    size_t needed = 0;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, "opx_octree_get_leaves", NULL,
                   opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, buffer, 2, &needed));
    assert_int_equal(needed, 5);
    assert_memory_equal(buffer, expected, 2 * sizeof buffer[0]);
    const unsigned char *rest = (const unsigned char *)&buffer[2];
    for (size_t i = 0; i < 6 * sizeof buffer[0]; ++i) assert_int_equal(rest[i], 0xAB);

    needed = 0;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, "opx_octree_get_leaves", NULL,
                   opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, NULL, 0, &needed));
    assert_int_equal(needed, 5);

    memset(buffer, 0xAB, sizeof buffer); /* larger than needed: the rest untouched */
    assert_ok(opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, buffer, 8, &needed));
    assert_int_equal(needed, 5);
    assert_memory_equal(buffer, expected, 5 * sizeof buffer[0]);
    assert_int_equal(((const unsigned char *)&buffer[5])[0], 0xAB);
    free(expected);
    opx_octree_destroy(tree);
}

static void leaves_reject_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_ray_map();
    const char *fn = "opx_octree_get_leaves";
    opx_leaf buffer[8];
    size_t count = 0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree",
                   opx_octree_get_leaves(NULL, OPX_MASK_ALL_KNOWN, buffer, 8, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_count",
                   opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, buffer, 8, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_leaves",
                   opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, NULL, 8, &count));
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(classify_unknown_gives_the_largest_unobserved_cube),
        cmocka_unit_test(classify_at_the_edges_of_the_cube),
        cmocka_unit_test(classify_rejects_bad_arguments),
        cmocka_unit_test(classify_writes_no_further_than_struct_size),
        cmocka_unit_test(stats_of_an_empty_map_are_zero),
        cmocka_unit_test(stats_count_and_bound_the_cells),
        cmocka_unit_test(stats_reject_bad_arguments),
        cmocka_unit_test(leaves_come_depth_first_with_their_values),
        cmocka_unit_test(leaves_are_filtered_by_class_mask),
        cmocka_unit_test(leaves_buffer_too_small_reports_needed_count),
        cmocka_unit_test(leaves_reject_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
