/* opx_octree_insert_points: every invalid argument is rejected, named in
 * the message, and leaves the map unchanged; the report and its counters. */
#include "opx_test.h"

static const char *const FN = "opx_octree_insert_points";

/* Four valid points (sensor frame) for the calls under test. */
static const double POINTS64[12] = {0.5, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0, 0.5, 0.7, 0.7, 0.0};
static const float POINTS32[12] = {0.5f, 0.0f, 0.0f, 0.0f, 0.5f, 0.0f,
                                   0.0f, 0.0f, 0.5f, 0.7f, 0.7f, 0.0f};

/* Calls insert with these arguments on the sample map, expects `expected`
 * naming `argument`, and checks the map did not change. */
static void expect_insert_fails(const void *points, size_t count, size_t stride, int32_t scalar,
                                const opx_insert_options *options, opx_insert_report *report,
                                opx_status expected, const char *argument) {
    opx_octree *tree = new_sample_map();
    map_snapshot before = take_snapshot(tree);
    expect_failure(expected, FN, argument,
                   opx_octree_insert_points(tree, points, count, stride, scalar, options, report));
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
}

static void expect_pose_fails(opx_pose pose) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.sensor_pose = pose;
    expect_insert_fails(POINTS64, 4, 0, OPX_SCALAR_FLOAT64, &options, NULL,
                        OPX_ERROR_INVALID_ARGUMENT, "sensor_pose");
}

static void rejects_null_tree(void **state) {
    (void)state;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "tree",
                   opx_octree_insert_points(NULL, POINTS64, 4, 0, OPX_SCALAR_FLOAT64, NULL, NULL));
}

static void rejects_null_points_with_count(void **state) {
    (void)state;
    expect_insert_fails(NULL, 1, 0, OPX_SCALAR_FLOAT64, NULL, NULL, OPX_ERROR_INVALID_ARGUMENT,
                        "points");
    expect_insert_fails(NULL, 4, 24, OPX_SCALAR_FLOAT32, NULL, NULL, OPX_ERROR_INVALID_ARGUMENT,
                        "points");
}

static void rejects_bad_scalar_type(void **state) {
    (void)state;
    const int32_t bad[] = {0, 3, -1, OPX_SCALAR_FLOAT64 + 100};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        expect_insert_fails(POINTS64, 4, 0, bad[i], NULL, NULL, OPX_ERROR_INVALID_ARGUMENT,
                            "scalar_type");
}

static void rejects_stride_smaller_than_a_point(void **state) {
    (void)state;
    const size_t bad32[] = {1, 4, 8, 11};
    for (size_t i = 0; i < sizeof bad32 / sizeof bad32[0]; ++i)
        expect_insert_fails(POINTS32, 4, bad32[i], OPX_SCALAR_FLOAT32, NULL, NULL,
                            OPX_ERROR_INVALID_ARGUMENT, "stride");
    const size_t bad64[] = {1, 8, 12, 16, 23};
    for (size_t i = 0; i < sizeof bad64 / sizeof bad64[0]; ++i)
        expect_insert_fails(POINTS64, 4, bad64[i], OPX_SCALAR_FLOAT64, NULL, NULL,
                            OPX_ERROR_INVALID_ARGUMENT, "stride");
}

/* Strides that would overflow count * stride must not be trusted. */
static void rejects_stride_overflowing_the_address_space(void **state) {
    (void)state;
    expect_insert_fails(POINTS64, 4, SIZE_MAX / 2, OPX_SCALAR_FLOAT64, NULL, NULL,
                        OPX_ERROR_INVALID_ARGUMENT, NULL);
}

static void rejects_options_struct_size_zero(void **state) {
    (void)state;
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.struct_size = 0;
    expect_insert_fails(POINTS64, 4, 0, OPX_SCALAR_FLOAT64, &options, NULL, OPX_ERROR_VERSION,
                        "struct_size");
}

static void rejects_report_struct_size_zero(void **state) {
    (void)state;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    report.struct_size = 0;
    expect_insert_fails(POINTS64, 4, 0, OPX_SCALAR_FLOAT64, NULL, &report, OPX_ERROR_VERSION,
                        "struct_size");
}

static void rejects_bad_mode(void **state) {
    (void)state;
    const int32_t bad[] = {-1, 2, 1000};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
        options.mode = bad[i];
        expect_insert_fails(POINTS64, 4, 0, OPX_SCALAR_FLOAT64, &options, NULL,
                            OPX_ERROR_INVALID_ARGUMENT, "mode");
    }
}

static void rejects_non_finite_pose(void **state) {
    (void)state;
    const double bad[] = {NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < 3; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            opx_pose pose = OPX_POSE_IDENTITY;
            pose.position[axis] = bad[i];
            expect_pose_fails(pose);
        }
        for (int c = 0; c < 4; ++c) {
            opx_pose pose = OPX_POSE_IDENTITY;
            pose.orientation[c] = bad[i];
            expect_pose_fails(pose);
        }
    }
}

static void rejects_zero_quaternion(void **state) {
    (void)state;
    opx_pose pose = OPX_POSE_IDENTITY;
    pose.orientation[3] = 0.0;
    expect_pose_fails(pose);
}

static void rejects_nan_max_range(void **state) {
    (void)state;
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.max_range = NAN;
    expect_insert_fails(POINTS64, 4, 0, OPX_SCALAR_FLOAT64, &options, NULL,
                        OPX_ERROR_INVALID_ARGUMENT, "max_range");
}

/* A ray-casting sensor outside the addressable cube cannot clear space. */
static void rejects_sensor_outside_the_map(void **state) {
    (void)state;
    const opx_insert_options options = sensor_at(RES * 40000.0, 0.0, 0.0, OPX_INSERT_RAYCAST);
    expect_insert_fails(POINTS64, 4, 0, OPX_SCALAR_FLOAT64, &options, NULL,
                        OPX_ERROR_INVALID_ARGUMENT, "sensor_pose");
}

static void assert_zero_report(const opx_insert_report *r) {
    assert_int_equal(r->struct_size, sizeof *r);
    assert_int_equal(r->points_used + r->points_nonfinite + r->points_out_of_range +
                         r->points_outside_map + r->cells_hit + r->cells_missed,
                     0);
}

/* count 0 is valid: nothing changes and the report is zeroed. */
static void count_zero_is_a_no_op(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    map_snapshot before = take_snapshot(tree);
    opx_insert_report report;
    memset(&report, 0x5A, sizeof report);
    report.struct_size = sizeof report;
    assert_ok(opx_octree_insert_points(tree, POINTS64, 0, 0, OPX_SCALAR_FLOAT64, NULL, &report));
    assert_zero_report(&report);
    memset(&report, 0x5A, sizeof report);
    report.struct_size = sizeof report;
    assert_ok(opx_octree_insert_points(tree, NULL, 0, 0, OPX_SCALAR_FLOAT32, NULL, &report));
    assert_zero_report(&report);
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
}

/* Every point is counted once: used + nonfinite + out_of_range +
 * outside_map == count.  The sensor sits near the +x face of the cube so a
 * point 1 m ahead leaves the map while staying within max_range. */
static void report_counters_add_up_to_count(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const double edge = 32768.0 * RES - C0; /* centre of the last cell along +x */
    const double xyz[] = {
        -1.0, 0.0,  0.0, /* used: 1 hit, 4 cells ahead of it */
        0.0,  -2.0, 0.0, /* used: 1 hit, 7 free cells (the origin's counted above) */
        NAN,  0.0,  0.0, /* nonfinite */
        0.0,  INFINITY, 0.0, /* nonfinite */
        -6.0, 0.0,  0.0, /* beyond max_range 5: cut, 20 cells to 5 m, the hit above among them */
        1.0,  0.0,  0.0, /* outside the map cube */
    };
    opx_insert_options options = sensor_at(edge, C0, C0, OPX_INSERT_RAYCAST);
    options.max_range = 5.0;
    const opx_insert_report r = insert_f64(tree, xyz, 6, &options);
    assert_int_equal(r.points_used, 2);
    assert_int_equal(r.points_nonfinite, 2);
    assert_int_equal(r.points_out_of_range, 1);
    assert_int_equal(r.points_outside_map, 1);
    assert_int_equal(r.cells_hit, 2);
    assert_int_equal(r.cells_missed, 19 + 7);
    const opx_octree_stats stats = stats_of(tree);
    assert_int_equal(stats.leaves_occupied, 2);
    assert_int_equal(stats.leaves_free, 19 + 7);
    opx_octree_destroy(tree);
}

/* Points far beyond the cube (no int key could hold them) count as outside
 * the map, in both modes. */
static void far_points_count_as_outside_the_map(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const double xyz[] = {0.0, 1e30, 0.0, -1e300, 0.0, 0.0, 0.0, 0.0, 1e10};
    for (int32_t mode = OPX_INSERT_RAYCAST; mode <= OPX_INSERT_ENDPOINTS; ++mode) {
        const opx_insert_options options = sensor_at(C0, C0, C0, mode);
        const opx_insert_report r = insert_f64(tree, xyz, 3, &options);
        assert_int_equal(r.points_outside_map, 3);
        assert_int_equal(r.points_used + r.cells_hit + r.cells_missed, 0);
    }
    assert_int_equal(stats_of(tree).inner_nodes, 0);
    opx_octree_destroy(tree);
}

/* An older caller's report is written no further than its struct_size. */
static void report_is_written_no_further_than_struct_size(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    opx_insert_report report;
    memset(&report, 0x5A, sizeof report);
    report.struct_size = (uint32_t)offsetof(opx_insert_report, points_nonfinite);
    assert_ok(opx_octree_insert_points(tree, POINTS64, 4, 0, OPX_SCALAR_FLOAT64, NULL, &report));
    assert_int_equal(report.struct_size, offsetof(opx_insert_report, points_nonfinite));
    assert_int_equal(report.points_used, 4);
    const unsigned char *bytes = (const unsigned char *)&report;
    for (size_t i = offsetof(opx_insert_report, points_nonfinite); i < sizeof report; ++i)
        assert_int_equal(bytes[i], 0x5A);
    opx_octree_destroy(tree);
}

/* An older caller's options: max_range (unknown to it) keeps its default,
 * no limit, whatever lies in memory. */
static void options_are_read_no_further_than_struct_size(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    options.max_range = 0.5;
    options.struct_size = (uint32_t)offsetof(opx_insert_options, max_range);
    const double xyz[3] = {2.0, 0.0, 0.0};
    const opx_insert_report r = insert_f64(tree, xyz, 1, &options);
    assert_int_equal(r.points_used, 1);
    assert_int_equal(r.points_out_of_range, 0);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rejects_null_tree),
        cmocka_unit_test(rejects_null_points_with_count),
        cmocka_unit_test(rejects_bad_scalar_type),
        cmocka_unit_test(rejects_stride_smaller_than_a_point),
        cmocka_unit_test(rejects_options_struct_size_zero),
        cmocka_unit_test(rejects_report_struct_size_zero),
        cmocka_unit_test(rejects_bad_mode),
        cmocka_unit_test(rejects_non_finite_pose),
        cmocka_unit_test(rejects_zero_quaternion),
        cmocka_unit_test(rejects_nan_max_range),
        cmocka_unit_test(rejects_sensor_outside_the_map),
        cmocka_unit_test(count_zero_is_a_no_op),
        cmocka_unit_test(report_counters_add_up_to_count),
        cmocka_unit_test(far_points_count_as_outside_the_map),
        cmocka_unit_test(report_is_written_no_further_than_struct_size),
        cmocka_unit_test(options_are_read_no_further_than_struct_size),
        /* Last: without a check it crashes, which under ASan ends the run. */
        cmocka_unit_test(rejects_stride_overflowing_the_address_space),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
