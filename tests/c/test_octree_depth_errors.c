/* opx_octree_insert_depth_image: every invalid argument is rejected with a
 * message naming the function and the argument, and leaves the map as it
 * was. */
#include "opx_depth_test.h"

static const char *const FN = "opx_octree_insert_depth_image";

/* Calls insert on the sample map with these arguments (NULL options and
 * report are passed as NULL), expects `expected` naming `argument`, and
 * checks the map did not change. */
static void expect_depth_fails(const opx_depth_image *image, const opx_camera_intrinsics *camera,
                               const opx_insert_options *options, opx_insert_report *report,
                               opx_status expected, const char *argument) {
    opx_octree *tree = new_sample_map();
    map_snapshot before = take_snapshot(tree);
    expect_failure(expected, FN, argument,
                   opx_octree_insert_depth_image(tree, image, camera, options, report));
    assert_unchanged(tree, &before);
    opx_octree_destroy(tree);
}

/* The tiny frame with one field of the image changed by `edit`. */
#define EXPECT_IMAGE_FAILS(edit, argument)                                               \
    do {                                                                                 \
        const opx_camera_intrinsics camera_ = tiny_camera();                             \
        opx_depth_image image = tiny_image_mm();                                         \
        edit;                                                                            \
        expect_depth_fails(&image, &camera_, NULL, NULL, OPX_ERROR_INVALID_ARGUMENT,     \
                           (argument));                                                  \
    } while (0)

#define EXPECT_CAMERA_FAILS(edit, argument)                                              \
    do {                                                                                 \
        const opx_depth_image image_ = tiny_image_mm();                                  \
        opx_camera_intrinsics camera = tiny_camera();                                    \
        edit;                                                                            \
        expect_depth_fails(&image_, &camera, NULL, NULL, OPX_ERROR_INVALID_ARGUMENT,     \
                           (argument));                                                  \
    } while (0)

static void rejects_null_arguments(void **state) {
    (void)state;
    const opx_depth_image image = tiny_image_mm();
    const opx_camera_intrinsics camera = tiny_camera();
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, FN, "tree",
                   opx_octree_insert_depth_image(NULL, &image, &camera, NULL, NULL));
    expect_depth_fails(NULL, &camera, NULL, NULL, OPX_ERROR_INVALID_ARGUMENT, "image");
    expect_depth_fails(&image, NULL, NULL, NULL, OPX_ERROR_INVALID_ARGUMENT, "intrinsics");
    EXPECT_IMAGE_FAILS(image.data = NULL, "image.data");
}

static void rejects_struct_size_zero(void **state) {
    (void)state;
    opx_depth_image image = tiny_image_mm();
    opx_camera_intrinsics camera = tiny_camera();
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    image.struct_size = 0;
    expect_depth_fails(&image, &camera, NULL, NULL, OPX_ERROR_VERSION, "image");
    image.struct_size = sizeof image;
    camera.struct_size = 0;
    expect_depth_fails(&image, &camera, NULL, NULL, OPX_ERROR_VERSION, "intrinsics");
    camera.struct_size = sizeof camera;
    options.struct_size = 0;
    expect_depth_fails(&image, &camera, &options, NULL, OPX_ERROR_VERSION, "options");
    report.struct_size = 0;
    expect_depth_fails(&image, &camera, NULL, &report, OPX_ERROR_VERSION, "out_report");
}

static void rejects_bad_scalar_type(void **state) {
    (void)state;
    const int32_t bad[] = {0, OPX_SCALAR_FLOAT64, 4, -1, 1000};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        EXPECT_IMAGE_FAILS(image.scalar_type = bad[i], "image.scalar_type");
}

static void rejects_rows_shorter_than_width(void **state) {
    (void)state;
    for (size_t stride = 1; stride < 2 * TINY_W; ++stride)
        EXPECT_IMAGE_FAILS(image.row_stride = stride, "image.row_stride");
    /* float32 rows are twice as long. */
    EXPECT_IMAGE_FAILS((image.scalar_type = OPX_SCALAR_FLOAT32, image.row_stride = 2 * TINY_W),
                       "image.row_stride");
}

/* Sizes whose bytes or points overflow size_t are refused before a byte
 * is read. */
static void rejects_absurd_sizes(void **state) {
    (void)state;
    EXPECT_IMAGE_FAILS(image.width = SIZE_MAX, "image.width");
    EXPECT_IMAGE_FAILS((image.width = SIZE_MAX / 4 + 1, image.scalar_type = OPX_SCALAR_FLOAT32),
                       "image.width");
    EXPECT_IMAGE_FAILS(image.height = SIZE_MAX, "image.height");
    EXPECT_IMAGE_FAILS((image.height = 3, image.row_stride = SIZE_MAX / 2), "image.height");
    /* Rows that fit in the address space, pixels whose points would not. */
    EXPECT_IMAGE_FAILS((image.width = (size_t)1 << 31, image.height = (size_t)1 << 31),
                       "image.width * image.height");
}

static void rejects_bad_depth_scale(void **state) {
    (void)state;
    const double bad[] = {0.0, -1000.0, NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        EXPECT_IMAGE_FAILS(image.depth_scale = bad[i], "image.depth_scale");
}

/* A float32 image is in metres: its depth_scale is not read. */
static void float_images_ignore_depth_scale(void **state) {
    (void)state;
    float metres[TINY_H][TINY_W];
    tiny_metres(metres);
    const opx_camera_intrinsics camera = tiny_camera();
    opx_depth_image image = float_image(&metres[0][0], TINY_W, TINY_H);
    image.depth_scale = NAN;
    opx_octree *tree = new_tree(RES);
    const opx_insert_report r = insert_depth(tree, &image, &camera, NULL);
    assert_int_equal(r.points_used, TINY_VALID);
    opx_octree_destroy(tree);
}

static void rejects_bad_intrinsics(void **state) {
    (void)state;
    const double bad_focal[] = {0.0, -525.0, NAN, INFINITY, -INFINITY};
    const double bad_centre[] = {NAN, INFINITY, -INFINITY};
    for (size_t i = 0; i < sizeof bad_focal / sizeof bad_focal[0]; ++i) {
        EXPECT_CAMERA_FAILS(camera.fx = bad_focal[i], "intrinsics.fx");
        EXPECT_CAMERA_FAILS(camera.fy = bad_focal[i], "intrinsics.fy");
    }
    for (size_t i = 0; i < sizeof bad_centre / sizeof bad_centre[0]; ++i) {
        EXPECT_CAMERA_FAILS(camera.cx = bad_centre[i], "intrinsics.cx");
        EXPECT_CAMERA_FAILS(camera.cy = bad_centre[i], "intrinsics.cy");
    }
    /* The defaults (all 0) are not a camera. */
    const opx_camera_intrinsics unset = OPX_CAMERA_INTRINSICS_INIT;
    const opx_depth_image image = tiny_image_mm();
    expect_depth_fails(&image, &unset, NULL, NULL, OPX_ERROR_INVALID_ARGUMENT, "intrinsics.fx");
}

static void rejects_bad_insert_options(void **state) {
    (void)state;
    const opx_depth_image image = tiny_image_mm();
    const opx_camera_intrinsics camera = tiny_camera();
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.mode = 2;
    expect_depth_fails(&image, &camera, &options, NULL, OPX_ERROR_INVALID_ARGUMENT, "options.mode");
    options.mode = OPX_INSERT_RAYCAST;
    options.max_range = NAN;
    expect_depth_fails(&image, &camera, &options, NULL, OPX_ERROR_INVALID_ARGUMENT,
                       "options.max_range");
    options.max_range = -1.0;
    options.sensor_pose.orientation[3] = 0.0;
    expect_depth_fails(&image, &camera, &options, NULL, OPX_ERROR_INVALID_ARGUMENT,
                       "sensor_pose");
    /* A ray-casting camera outside the addressable cube. */
    options = sensor_at(RES * 40000.0, 0.0, 0.0, OPX_INSERT_RAYCAST);
    expect_depth_fails(&image, &camera, &options, NULL, OPX_ERROR_INVALID_ARGUMENT,
                       "sensor_pose");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(rejects_null_arguments),
        cmocka_unit_test(rejects_struct_size_zero),
        cmocka_unit_test(rejects_bad_scalar_type),
        cmocka_unit_test(rejects_rows_shorter_than_width),
        cmocka_unit_test(rejects_bad_depth_scale),
        cmocka_unit_test(float_images_ignore_depth_scale),
        cmocka_unit_test(rejects_bad_intrinsics),
        cmocka_unit_test(rejects_bad_insert_options),
        /* Last: without a check they read far past the image, which under
         * ASan ends the run. */
        cmocka_unit_test(rejects_absurd_sizes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
