/*
 * Clearing, decay, cropping and bounded inserts through the C ABI: the
 * cells a box covers at its faces (the cell above a face is in, as
 * opx_octree_classify places a point on it), values after decay, memory
 * after a crop, and bad input: an error naming the argument and the map
 * unchanged.  unit_map_edit checks every cell of random maps.
 */
#include "opx_test.h"

/* A row of 8 cells along x at RES (x from 0 to 2), each hit once. */
static opx_octree *row_map(void) {
    opx_octree *tree = new_tree(RES);
    double xyz[24];
    for (int i = 0; i < 8; ++i) {
        xyz[3 * i] = (i + 0.5) * RES;
        xyz[3 * i + 1] = C0;
        xyz[3 * i + 2] = C0;
    }
    const opx_insert_options options = sensor_at(0, 0, 0, OPX_INSERT_ENDPOINTS);
    insert_f64(tree, xyz, 8, &options);
    return tree;
}

static int32_t class_at_x(const opx_octree *tree, int cell) {
    return classify_at(tree, (cell + 0.5) * RES, C0, C0).cell_class;
}

static void box_faces_follow_classify(void **state) {
    (void)state;
    opx_octree *tree = row_map();
    /* x from 0.5 to 1.0: the cells [0.5, 0.75), [0.75, 1.0) and [1.0, 1.25). */
    const double lo[3] = {0.5, 0.0, 0.0}, hi[3] = {1.0, 0.0, 0.0};
    assert_ok(opx_octree_clear_region(tree, lo, hi, OPX_CELL_UNKNOWN));
    const int32_t expected[8] = {OPX_CELL_OCCUPIED, OPX_CELL_OCCUPIED, OPX_CELL_UNKNOWN, OPX_CELL_UNKNOWN,
                                 OPX_CELL_UNKNOWN, OPX_CELL_OCCUPIED, OPX_CELL_OCCUPIED, OPX_CELL_OCCUPIED};
    for (int i = 0; i < 8; ++i) assert_int_equal(class_at_x(tree, i), expected[i]);
    /* Just below a face: the cell below it only. */
    const double lo2[3] = {1.5 + 1e-9, 0.0, 0.0}, hi2[3] = {1.75 - 1e-9, 0.0, 0.0};
    assert_ok(opx_octree_clear_region(tree, lo2, hi2, OPX_CELL_FREE));
    assert_int_equal(class_at_x(tree, 5), OPX_CELL_OCCUPIED);
    assert_int_equal(class_at_x(tree, 6), OPX_CELL_FREE);
    assert_int_equal(class_at_x(tree, 7), OPX_CELL_OCCUPIED);
    assert_near(classify_at(tree, 6.5 * RES, C0, C0).probability, 0.1192, OPX_PROB_TOL);
    /* To free, unknown cells too: a box of 2 x 1 x 1 cells beside the row. */
    const double lo3[3] = {0.0, 0.3, 0.0}, hi3[3] = {0.3, 0.3, 0.0};
    assert_ok(opx_octree_clear_region(tree, lo3, hi3, OPX_CELL_FREE));
    assert_int_equal(classify_at(tree, C0, 0.375, C0).cell_class, OPX_CELL_FREE);
    assert_int_equal(classify_at(tree, 0.375, 0.375, C0).cell_class, OPX_CELL_FREE);
    assert_int_equal(classify_at(tree, 0.625, 0.375, C0).cell_class, OPX_CELL_UNKNOWN);
    opx_octree_destroy(tree);
}

static void crop_and_bounds_agree_at_faces(void **state) {
    (void)state;
    opx_octree *tree = row_map();
    const double lo[3] = {0.25, -1.0, -1.0}, hi[3] = {1.0, 1.0, 1.0};
    assert_ok(opx_octree_crop(tree, lo, hi));
    for (int i = 0; i < 8; ++i)
        assert_int_equal(class_at_x(tree, i), i >= 1 && i <= 4 ? OPX_CELL_OCCUPIED : OPX_CELL_UNKNOWN);
    /* The same box as insert bounds: a frame of the whole row changes
     * cells 1 to 4 alone. */
    opx_octree *bounded = new_tree(RES);
    double xyz[24];
    for (int i = 0; i < 8; ++i) {
        xyz[3 * i] = (i + 0.5) * RES;
        xyz[3 * i + 1] = C0;
        xyz[3 * i + 2] = C0;
    }
    opx_insert_options options = sensor_at(0, 0, 0, OPX_INSERT_ENDPOINTS);
    options.use_bounds = 1;
    for (int axis = 0; axis < 3; ++axis) {
        options.bounds_min[axis] = lo[axis];
        options.bounds_max[axis] = hi[axis];
    }
    const opx_insert_report report = insert_f64(bounded, xyz, 8, &options);
    assert_int_equal(report.points_used, 8);
    assert_int_equal(report.cells_hit, 4);
    assert_same_known_leaves(bounded, tree);
    opx_octree_destroy(bounded);
    opx_octree_destroy(tree);
}

static void decay_moves_toward_zero(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    /* Occupied cells at log-odds(0.7) = 0.847, free ones at log-odds(0.4) = -0.405. */
    assert_ok(opx_octree_decay(tree, 0.3));
    const opx_cell_info hit = classify_at(tree, 1.125, C0, C0);
    assert_int_equal(hit.cell_class, OPX_CELL_OCCUPIED);
    assert_near(hit.probability, probability(log_odds(0.7) - 0.3), OPX_PROB_TOL);
    const opx_cell_info miss = classify_at(tree, 0.375, C0, C0);
    assert_int_equal(miss.cell_class, OPX_CELL_FREE);
    assert_near(miss.probability, probability(log_odds(0.4) + 0.3), OPX_PROB_TOL);
    /* The free cells reach 0 and go; the occupied ones stay. */
    assert_ok(opx_octree_decay(tree, 0.3));
    assert_int_equal(classify_at(tree, 0.375, C0, C0).cell_class, OPX_CELL_UNKNOWN);
    assert_int_equal(classify_at(tree, 1.125, C0, C0).cell_class, OPX_CELL_OCCUPIED);
    const opx_octree_stats stats = stats_of(tree);
    assert_int_equal(stats.leaves_free, 0);
    assert_int_equal(stats.leaves_occupied, 2);
    assert_ok(opx_octree_decay(tree, 0.0));
    assert_ok(opx_octree_decay(tree, INFINITY));
    assert_int_equal(stats_of(tree).leaves_occupied, 0);
    opx_octree_destroy(tree);
}

static void shapes_clear_what_they_touch(void **state) {
    (void)state;
    opx_octree *tree = row_map();
    opx_shape sphere = OPX_SHAPE_INIT;
    sphere.kind = OPX_SHAPE_SPHERE;
    sphere.radius = 0.2;
    sphere.pose.position[0] = 0.1; /* in the object frame */
    opx_pose pose = OPX_POSE_IDENTITY;
    pose.position[0] = 0.9; /* the sphere's centre at x = 1.0, y = 0, z = 0 */
    assert_ok(opx_octree_clear_shapes(tree, &sphere, 1, &pose, OPX_CELL_UNKNOWN));
    /* It reaches x from 0.8 to 1.2 and touches the row's cells 3 and 4
     * (y and z from 0 to 0.25: the sphere's centre lies on their faces). */
    for (int i = 0; i < 8; ++i)
        assert_int_equal(class_at_x(tree, i), i == 3 || i == 4 ? OPX_CELL_UNKNOWN : OPX_CELL_OCCUPIED);
    assert_ok(opx_octree_clear_shapes(tree, NULL, 0, NULL, OPX_CELL_FREE));
    opx_octree_destroy(tree);
}

static void bad_input_changes_nothing(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    map_snapshot before = take_snapshot(tree);
    const double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {1.0, 1.0, 1.0};
    const double inverted[3] = {1.0, -1.0, 1.0}, nan_box[3] = {0.0, NAN, 0.0};
    const char *fn = "opx_octree_clear_region";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree", opx_octree_clear_region(NULL, lo, hi, OPX_CELL_FREE));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "box_min", opx_octree_clear_region(tree, NULL, hi, OPX_CELL_FREE));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "box_min", opx_octree_clear_region(tree, nan_box, hi, OPX_CELL_FREE));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "box_max", opx_octree_clear_region(tree, lo, nan_box, OPX_CELL_FREE));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "inverted", opx_octree_clear_region(tree, lo, inverted, OPX_CELL_FREE));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "to", opx_octree_clear_region(tree, lo, hi, OPX_CELL_OCCUPIED));
    const double far[3] = {1.0, INFINITY, 1.0};
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "finite", opx_octree_clear_region(tree, lo, far, OPX_CELL_FREE));
    fn = "opx_octree_crop";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "box_max", opx_octree_crop(tree, lo, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "inverted", opx_octree_crop(tree, lo, inverted));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "box_min", opx_octree_crop(tree, nan_box, hi));
    fn = "opx_octree_decay";
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "amount", opx_octree_decay(tree, NAN));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "amount", opx_octree_decay(tree, -0.1));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "amount", opx_octree_decay(tree, -INFINITY));
    fn = "opx_octree_clear_shapes";
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_SPHERE;
    shape.radius = -1.0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "shapes[0]", opx_octree_clear_shapes(tree, &shape, 1, NULL, OPX_CELL_FREE));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "shapes", opx_octree_clear_shapes(tree, NULL, 1, NULL, OPX_CELL_FREE));
    shape.radius = 0.5;
    opx_pose pose = OPX_POSE_IDENTITY;
    pose.orientation[3] = NAN;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "pose", opx_octree_clear_shapes(tree, &shape, 1, &pose, OPX_CELL_FREE));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "to", opx_octree_clear_shapes(tree, &shape, 1, NULL, 7));
    fn = "opx_octree_insert_points";
    opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    options.use_bounds = 1;
    options.bounds_max[1] = NAN;
    const double xyz[3] = {1.0, 0.0, 0.0};
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "options.bounds_max",
                   opx_octree_insert_points(tree, xyz, 1, 0, OPX_SCALAR_FLOAT64, &options, NULL));
    options.bounds_max[1] = 0.0;
    options.bounds_min[2] = 1.0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "options.bounds_min",
                   opx_octree_insert_points(tree, xyz, 1, 0, OPX_SCALAR_FLOAT64, &options, NULL));
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(box_faces_follow_classify),
        cmocka_unit_test(crop_and_bounds_agree_at_faces),
        cmocka_unit_test(decay_moves_toward_zero),
        cmocka_unit_test(shapes_clear_what_they_touch),
        cmocka_unit_test(bad_input_changes_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
