/* opx_octree_insert_depth_image: a hand-computed frame gives the map of its
 * points, uint16 and float32 frames agree, row strides and unaligned rows
 * are read, options pass through, and every pixel is counted once. */
#include "opx_depth_test.h"

#include <float.h>

/* The map of the hand-computed points, inserted as points. */
static opx_octree *map_of_tiny_points(const opx_insert_options *options, opx_insert_report *out) {
    opx_octree *tree = new_tree(RES);
    *out = insert_f64(tree, &TINY_POINTS[0][0], TINY_VALID, options);
    return tree;
}

static void tiny_frame_gives_the_map_of_its_points(void **state) {
    (void)state;
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    const opx_camera_intrinsics camera = tiny_camera();
    const opx_depth_image image = tiny_image_mm();
    opx_insert_report expected;
    opx_octree *reference = map_of_tiny_points(&options, &expected);
    opx_octree *tree = new_tree(RES);
    const opx_insert_report r = insert_depth(tree, &image, &camera, &options);
    assert_int_equal(r.points_used, TINY_VALID);
    assert_int_equal(r.pixels_no_return, TINY_NO_RETURN);
    assert_int_equal(r.points_nonfinite + r.points_out_of_range + r.points_outside_map, 0);
    assert_int_equal(r.cells_hit, TINY_VALID);
    assert_int_equal(r.cells_hit, expected.cells_hit);
    assert_int_equal(r.cells_missed, expected.cells_missed);
    assert_pixels_add_up(&r, TINY_W * TINY_H);
    assert_same_maps(tree, reference);
    /* Each endpoint's cell is occupied, in the map frame. */
    for (int i = 0; i < TINY_VALID; ++i) {
        const double *p = TINY_POINTS[i];
        const opx_cell_info cell = classify_at(tree, C0 + p[0], C0 + p[1], C0 + p[2]);
        assert_int_equal(cell.cell_class, OPX_CELL_OCCUPIED);
        assert_center(cell.center, C0 + p[0], C0 + p[1], C0 + p[2]);
    }
    /* Where the pixel (2, 1) without a return would have been seen at 2 m,
     * nothing was observed. */
    assert_int_equal(classify_at(tree, C0 + 0.5, C0, C0 + 2.0).cell_class, OPX_CELL_UNKNOWN);
    opx_octree_destroy(tree);
    opx_octree_destroy(reference);
}

static void float_metres_and_uint16_agree(void **state) {
    (void)state;
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    const opx_camera_intrinsics camera = tiny_camera();
    float metres[TINY_H][TINY_W];
    tiny_metres(metres);
    const opx_depth_image mm = tiny_image_mm(), m = float_image(&metres[0][0], TINY_W, TINY_H);
    opx_octree *a = new_tree(RES), *b = new_tree(RES);
    const opx_insert_report ra = insert_depth(a, &mm, &camera, &options);
    const opx_insert_report rb = insert_depth(b, &m, &camera, &options);
    assert_memory_equal(&ra, &rb, sizeof ra);
    assert_same_maps(a, b);
    opx_octree_destroy(a);
    opx_octree_destroy(b);
}

/* A 64 x 48 ramp in units of 1/1024 m, exact in float: uint16 with
 * depth_scale 1024 and float32 metres give the same map, at a camera of
 * realistic intrinsics with a pose. */
static void a_larger_frame_agrees_in_both_types(void **state) {
    (void)state;
    enum { W = 64, H = 48 };
    static uint16_t units[H][W];
    static float metres[H][W];
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) {
            units[v][u] = (u * 7 + v * 13) % 17 == 0 ? 0 : (uint16_t)(1024 + 37 * u + 11 * v);
            metres[v][u] = (float)units[v][u] / 1024.0f;
        }
    opx_camera_intrinsics camera = OPX_CAMERA_INTRINSICS_INIT;
    camera.fx = 52.5, camera.fy = 51.0, camera.cx = 31.5, camera.cy = 23.75;
    opx_insert_options options = sensor_at(0.3, -0.2, 1.1, OPX_INSERT_RAYCAST);
    options.sensor_pose.orientation[0] = -0.5, options.sensor_pose.orientation[1] = 0.5;
    options.sensor_pose.orientation[2] = -0.5, options.sensor_pose.orientation[3] = 0.5;
    opx_depth_image a = OPX_DEPTH_IMAGE_INIT;
    a.data = units, a.width = W, a.height = H, a.depth_scale = 1024.0;
    const opx_depth_image b = float_image(&metres[0][0], W, H);
    opx_octree *ta = new_tree(0.05), *tb = new_tree(0.05);
    const opx_insert_report ra = insert_depth(ta, &a, &camera, &options);
    const opx_insert_report rb = insert_depth(tb, &b, &camera, &options);
    assert_memory_equal(&ra, &rb, sizeof ra);
    assert_true(ra.pixels_no_return > 100 && ra.points_used > 2500);
    assert_pixels_add_up(&ra, W * H);
    assert_same_maps(ta, tb);
    opx_octree_destroy(ta);
    opx_octree_destroy(tb);
}

/* Rows with padding, starting at odd addresses (unaligned pixels). */
static void strided_unaligned_rows_are_read(void **state) {
    (void)state;
    enum { STRIDE = 2 * TINY_W + 5 };
    unsigned char bytes[1 + TINY_H * STRIDE];
    memset(bytes, 0xEE, sizeof bytes);
    for (int v = 0; v < TINY_H; ++v) memcpy(bytes + 1 + v * STRIDE, TINY_MM[v], sizeof TINY_MM[v]);
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    const opx_camera_intrinsics camera = tiny_camera();
    opx_depth_image image = tiny_image_mm();
    image.data = bytes + 1;
    image.row_stride = STRIDE;
    opx_insert_report expected;
    opx_octree *reference = map_of_tiny_points(&options, &expected);
    opx_octree *tree = new_tree(RES);
    const opx_insert_report r = insert_depth(tree, &image, &camera, &options);
    assert_int_equal(r.points_used, TINY_VALID);
    assert_int_equal(r.pixels_no_return, TINY_NO_RETURN);
    assert_same_maps(tree, reference);
    opx_octree_destroy(tree);
    opx_octree_destroy(reference);
}

/* Mode, max_range and pose reach the insert: the report equals the one of
 * the same points inserted as points. */
static void insert_options_pass_through(void **state) {
    (void)state;
    const opx_camera_intrinsics camera = tiny_camera();
    const opx_depth_image image = tiny_image_mm();
    for (int32_t mode = OPX_INSERT_RAYCAST; mode <= OPX_INSERT_ENDPOINTS; ++mode) {
        opx_insert_options options = sensor_at(C0 + 1.0, C0 - 2.0, C0, mode);
        options.max_range = 2.52; /* (-1.5, -0.5, 2) and (2.25, 0, 3) are farther */
        opx_insert_report expected;
        opx_octree *reference = map_of_tiny_points(&options, &expected);
        opx_octree *tree = new_tree(RES);
        opx_insert_report r = insert_depth(tree, &image, &camera, &options);
        assert_int_equal(r.points_out_of_range, 2);
        assert_int_equal(r.pixels_no_return, TINY_NO_RETURN);
        r.pixels_no_return = 0;
        assert_memory_equal(&r, &expected, sizeof r);
        assert_same_maps(tree, reference);
        opx_octree_destroy(tree);
        opx_octree_destroy(reference);
    }
}

/* A float depth whose point does not fit in float32 counts as non-finite;
 * NaN, infinities, zero and negative depths as no return. */
static void every_pixel_is_counted_once(void **state) {
    (void)state;
    const float metres[2][4] = {{FLT_MAX, 1.0f, NAN, -0.0f}, {-FLT_MAX, INFINITY, 1e-30f, 2.0f}};
    opx_camera_intrinsics camera = OPX_CAMERA_INTRINSICS_INIT;
    camera.fx = 0.5, camera.fy = 0.5, camera.cx = 0.0, camera.cy = 0.0;
    const opx_depth_image image = float_image(&metres[0][0], 4, 2);
    opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_ENDPOINTS);
    options.max_range = 100.0;
    opx_octree *tree = new_tree(RES);
    const opx_insert_report r = insert_depth(tree, &image, &camera, &options);
    /* (0,0) FLT_MAX: z alone fits, x = 0 and y = 0 too: out of range.
     * (1,0) 1 m: used.  (2,0), (3,0), (0,1), (1,1): no return.
     * (2,1) 1e-30 m: used (the origin's cell).  (3,1): x = (3 * 2 / 0.5) = 12,
     * y = 1 * 2 / 0.5 = 4: used. */
    assert_int_equal(r.pixels_no_return, 4);
    assert_int_equal(r.points_out_of_range, 1);
    assert_int_equal(r.points_used, 3);
    assert_pixels_add_up(&r, 8);
    /* A tiny focal length: x beyond float's range. */
    camera.fx = 1e-30;
    const float far[1][2] = {{1e30f, 1e30f}};
    const opx_depth_image wide = float_image(&far[0][0], 2, 1);
    const opx_insert_report w = insert_depth(tree, &wide, &camera, &options);
    assert_int_equal(w.points_nonfinite, 1); /* u = 1: x = 1e30 / 1e-30 */
    assert_int_equal(w.points_out_of_range, 1); /* u = 0: (0, 0, 1e30) */
    assert_pixels_add_up(&w, 2);
    opx_octree_destroy(tree);
}

/* An image with no pixel (width or height 0) changes nothing; data may be
 * NULL then. */
static void an_empty_image_changes_nothing(void **state) {
    (void)state;
    const opx_camera_intrinsics camera = tiny_camera();
    const size_t sizes[3][2] = {{0, 0}, {0, 5}, {5, 0}};
    opx_octree *tree = new_sample_map();
    map_snapshot before = take_snapshot(tree);
    for (int i = 0; i < 3; ++i) {
        opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
        image.width = sizes[i][0], image.height = sizes[i][1];
        opx_insert_report report;
        memset(&report, 0x5A, sizeof report);
        report.struct_size = sizeof report;
        assert_ok(opx_octree_insert_depth_image(tree, &image, &camera, NULL, &report));
        assert_int_equal(report.points_used + report.pixels_no_return + report.cells_hit, 0);
        image.data = TINY_MM;
        assert_ok(opx_octree_insert_depth_image(tree, &image, &camera, NULL, NULL));
    }
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
}

/* The init functions give the INIT values; a too small size is refused. */
static void init_functions_fill_the_defaults(void **state) {
    (void)state;
    const opx_depth_image image_init = OPX_DEPTH_IMAGE_INIT;
    const opx_camera_intrinsics camera_init = OPX_CAMERA_INTRINSICS_INIT;
    opx_depth_image image;
    opx_camera_intrinsics camera;
    memset(&image, 0x5A, sizeof image);
    memset(&camera, 0x5A, sizeof camera);
    assert_ok(opx_depth_image_init(&image, sizeof image));
    assert_ok(opx_camera_intrinsics_init(&camera, sizeof camera));
    assert_memory_equal(&image, &image_init, sizeof image);
    assert_memory_equal(&camera, &camera_init, sizeof camera);
    assert_int_equal(image.scalar_type, OPX_SCALAR_UINT16);
    assert_true(image.depth_scale == 1000.0);
    expect_failure(OPX_ERROR_VERSION, "opx_depth_image_init", "image",
                   opx_depth_image_init(&image, 2));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_camera_intrinsics_init", "intrinsics",
                   opx_camera_intrinsics_init(NULL, sizeof camera));
}

/* The report of an older caller (without pixels_no_return) is written no
 * further than its struct_size. */
static void an_older_report_is_not_overrun(void **state) {
    (void)state;
    const opx_camera_intrinsics camera = tiny_camera();
    const opx_depth_image image = tiny_image_mm();
    opx_insert_report report;
    memset(&report, 0x5A, sizeof report);
    report.struct_size = (uint32_t)offsetof(opx_insert_report, pixels_no_return);
    opx_octree *tree = new_tree(RES);
    assert_ok(opx_octree_insert_depth_image(tree, &image, &camera, NULL, &report));
    assert_int_equal(report.points_used, TINY_VALID);
    const unsigned char *bytes = (const unsigned char *)&report;
    for (size_t i = offsetof(opx_insert_report, pixels_no_return); i < sizeof report; ++i)
        assert_int_equal(bytes[i], 0x5A);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tiny_frame_gives_the_map_of_its_points),
        cmocka_unit_test(float_metres_and_uint16_agree),
        cmocka_unit_test(a_larger_frame_agrees_in_both_types),
        cmocka_unit_test(strided_unaligned_rows_are_read),
        cmocka_unit_test(insert_options_pass_through),
        cmocka_unit_test(every_pixel_is_counted_once),
        cmocka_unit_test(an_empty_image_changes_nothing),
        cmocka_unit_test(init_functions_fill_the_defaults),
        cmocka_unit_test(an_older_report_is_not_overrun),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
