/*
 * cli_ingest_depth: `octoprox ingest` on 16-bit depth images written here
 * (a PNG in TUM RGB-D units, 1/5000 m, and TIFFs in millimetres): the map
 * equals the library's own insert of the same pixels, with a cloud in the
 * same run too; the camera options without a depth image, a depth image
 * without them, and bad values exit 2; files that are not 16-bit depth
 * images exit 3 with a message naming them.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "depth_files.h"

#include <octoprox/octoprox.h>

#include <tiffio.h>

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#define W 40
#define H 30
#define INTRINSICS "40,40,19.5,14.5"
#define NO_RETURN 25 /* pixels (u, v) with u % 8 == 3 and v % 6 == 2 */

static uint16_t g_mm[H][W], g_tum[H][W];

/* A slanted wall 1.5 to 2.3 m ahead of the camera, with a grid of holes. */
static void make_frame(void) {
    int u, v;
    for (v = 0; v < H; ++v)
        for (u = 0; u < W; ++u) {
            const int hole = u % 8 == 3 && v % 6 == 2;
            g_mm[v][u] = hole ? 0 : (uint16_t)(1500 + 20 * u);
            g_tum[v][u] = (uint16_t)(5 * g_mm[v][u]);
        }
}

/* The library's map of the frame, camera 1 m above the origin. */
static opx_octree *library_map(void) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    opx_camera_intrinsics camera = OPX_CAMERA_INTRINSICS_INIT;
    opx_octree *tree = NULL;
    options.resolution = 0.1;
    insert.sensor_pose.position[2] = 1.0;
    image.data = g_mm, image.width = W, image.height = H, image.depth_scale = 1000.0;
    camera.fx = 40.0, camera.fy = 40.0, camera.cx = 19.5, camera.cy = 14.5;
    assert_int_equal(opx_octree_create(&options, &tree), OPX_OK);
    assert_int_equal(opx_octree_insert_depth_image(tree, &image, &camera, &insert, NULL), OPX_OK);
    return tree;
}

static opx_leaf *leaves_of(const opx_octree *tree, size_t *count) {
    opx_leaf *leaves;
    opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, NULL, 0, count);
    leaves = calloc(*count + 1, sizeof *leaves);
    assert_non_null(leaves);
    assert_int_equal(opx_octree_get_leaves(tree, OPX_MASK_ALL_KNOWN, leaves, *count, count), OPX_OK);
    return leaves;
}

/* The .ot file holds the same leaves, log-odds included, as `expected`. */
static void assert_map_file_equals(const char *path, const opx_octree *expected) {
    opx_octree *loaded = NULL;
    size_t n_loaded, n_expected;
    opx_leaf *a, *b;
    assert_int_equal(opx_octree_load_file(path, NULL, &loaded), OPX_OK);
    a = leaves_of(loaded, &n_loaded);
    b = leaves_of(expected, &n_expected);
    assert_true(n_expected > 20);
    assert_int_equal(n_loaded, n_expected);
    assert_memory_equal(a, b, n_expected * sizeof *a);
    free(a);
    free(b);
    opx_octree_destroy(loaded);
}

static void png_and_tiff_give_the_library_map(void **state) {
    static cli_result r;
    opx_octree *expected = library_map();
    const char *png = write_png("tum.png", &g_tum[0][0], W, H, 16, 1);
    const char *tiff = write_tiff("mm.tiff", &g_mm[0][0], W, H, 16, 1, COMPRESSION_PACKBITS);
    char map[512];
    (void)state;
    snprintf(map, sizeof map, "%s", scratch_path("png.ot"));
    run_cli(&r, "ingest '%s' --intrinsics " INTRINSICS " --depth-scale 5000 --sensor-pose 0,0,1 --res 0.1 -o '%s' --json",
            png, map);
    if (r.code != 0) fail_msg("exit %d: %s", r.code, r.err);
    assert_int_equal((long long)json_field(r.out, "points"), W * H);
    assert_int_equal((long long)json_field(r.out, "points_used"), W * H - NO_RETURN);
    assert_int_equal((long long)json_field(r.out, "pixels_no_return"), NO_RETURN);
    assert_non_null(strstr(r.out, "\"format\": \"png 16-bit gray\""));
    assert_map_file_equals(map, expected);
    snprintf(map, sizeof map, "%s", scratch_path("tiff.ot"));
    run_cli(&r, "ingest '%s' --intrinsics=" INTRINSICS " --depth-scale=1000 --sensor-pose 0,0,1 --res 0.1 -o '%s'", tiff,
            map);
    if (r.code != 0) fail_msg("exit %d: %s", r.code, r.err);
    assert_non_null(strstr(r.out, "1200 pixels, 1175 used, 25 skipped"));
    assert_map_file_equals(map, expected);
    opx_octree_destroy(expected);
}

/* A cloud and a depth image in one run: both frames go in, in order. */
static void clouds_and_depth_images_mix(void **state) {
    static cli_result r;
    const char *cloud = write_text("one.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                              "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n0 0 3\n");
    const char *tiff = write_tiff("mix.tif", &g_mm[0][0], W, H, 16, 1, COMPRESSION_NONE);
    (void)state;
    run_cli(&r, "ingest '%s' '%s' --intrinsics " INTRINSICS " --depth-scale 1000 -o '%s' --json", cloud, tiff,
            scratch_path("mix.bt"));
    if (r.code != 0) fail_msg("exit %d: %s", r.code, r.err);
    assert_non_null(strstr(r.out, "\"format\": \"pcd ascii\""));
    assert_non_null(strstr(r.out, "\"format\": \"tiff 16-bit gray\""));
}

static void expect_usage_error(const char *arguments, const char *message) {
    static cli_result r;
    run_cli(&r, "%s -o '%s'", arguments, scratch_path("never.bt"));
    if (r.code != 2) fail_msg("'octoprox %s' exited %d, not 2; stderr: %s", arguments, r.code, r.err);
    if (strstr(r.err, message) == NULL) fail_msg("'octoprox %s': stderr \"%s\" lacks \"%s\"", arguments, r.err, message);
}

static void camera_options_and_images_go_together(void **state) {
    char png[512], cloud[512]; /* copies: scratch paths are reused after four calls */
    static const char *const bad_intrinsics[] = {"40,40,19.5", "40,40,19.5,14.5,1", "0,40,19.5,14.5",
                                                 "40,-1,19.5,14.5", "40,40,nan,14.5", "40,40,19.5,", "a,b,c,d", ""};
    static const char *const bad_scales[] = {"0", "-1000", "nan", "inf", "mm"};
    char line[1024];
    size_t i;
    (void)state;
    snprintf(png, sizeof png, "%s", write_png("usage.png", &g_tum[0][0], W, H, 16, 1));
    snprintf(cloud, sizeof cloud, "%s",
             write_text("usage.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                     "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n0 0 3\n"));
    snprintf(line, sizeof line, "ingest '%s' --depth-scale 5000", png);
    expect_usage_error(line, "needs --intrinsics fx,fy,cx,cy");
    snprintf(line, sizeof line, "ingest '%s' --intrinsics " INTRINSICS, png);
    expect_usage_error(line, "needs --depth-scale S");
    snprintf(line, sizeof line, "ingest '%s' --intrinsics " INTRINSICS, cloud);
    expect_usage_error(line, "--intrinsics is for depth images");
    snprintf(line, sizeof line, "ingest '%s' --depth-scale 1000", cloud);
    expect_usage_error(line, "--depth-scale is for depth images");
    for (i = 0; i < sizeof bad_intrinsics / sizeof bad_intrinsics[0]; ++i) {
        snprintf(line, sizeof line, "ingest '%s' --depth-scale 5000 --intrinsics '%s'", png, bad_intrinsics[i]);
        expect_usage_error(line, "--intrinsics needs fx,fy,cx,cy");
    }
    for (i = 0; i < sizeof bad_scales / sizeof bad_scales[0]; ++i) {
        snprintf(line, sizeof line, "ingest '%s' --intrinsics " INTRINSICS " --depth-scale '%s'", png, bad_scales[i]);
        expect_usage_error(line, "--depth-scale needs a positive number");
    }
    expect_usage_error("ingest depth.pgm --intrinsics " INTRINSICS, "nor a .png, .tif or .tiff depth image");
}

static void expect_input_error(const char *path, const char *message) {
    static cli_result r;
    run_cli(&r, "ingest '%s' --intrinsics " INTRINSICS " --depth-scale 1000 -o '%s'", path, scratch_path("never.bt"));
    if (r.code != 3) fail_msg("%s: exit %d, not 3; stderr: %s", path, r.code, r.err);
    if (strstr(r.err, message) == NULL || strstr(r.err, path) == NULL)
        fail_msg("%s: stderr \"%s\" lacks \"%s\" or the file name", path, r.err, message);
}

static void files_that_are_not_depth_images_exit_3(void **state) {
    uint16_t bytes[H][W];
    const char *whole;
    int u, v;
    (void)state;
    for (v = 0; v < H; ++v)
        for (u = 0; u < W; ++u) bytes[v][u] = (uint16_t)(g_mm[v][u] & 0xff);
    expect_input_error(write_png("eight.png", &bytes[0][0], W, H, 8, 1), "8-bit grayscale");
    expect_input_error(write_tiff("float.tif", &g_mm[0][0], W, H, 32, 1, COMPRESSION_NONE), "16-bit unsigned");
    whole = write_png("whole.png", &g_tum[0][0], W, H, 16, 1);
    expect_input_error(write_prefix("cut.png", whole, file_size(whole) - 20), "unreadable PNG");
    expect_input_error(write_raw_png_header("huge.png", 30000, 30000), "more than");
    expect_input_error(write_raw_tiff("huge.tif", 30000, 30000, 1800000000u, 64), "more than");
    expect_input_error(write_text("text.tiff", "not an image\n"), "neither a PNG nor a TIFF");
    expect_input_error(scratch_path("missing.png"), "cannot open");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(png_and_tiff_give_the_library_map),
        cmocka_unit_test(clouds_and_depth_images_mix),
        cmocka_unit_test(camera_options_and_images_go_together),
        cmocka_unit_test(files_that_are_not_depth_images_exit_3),
    };
    make_frame();
    return cmocka_run_group_tests_name("cli_ingest_depth", tests, NULL, NULL);
}
