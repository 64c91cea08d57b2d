/* real_pcd_reader: the library's PCD reader on the real Kinect frame
 * (binary), on its LZF original (the same values), and on small files
 * written here. */
#define _POSIX_C_SOURCE 200809L

#include "opx_data_test.h"
#include "pcd_reader.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#define FRAME_STEM "rgbd/frame_20121214T142255.814212"

static char g_binary_path[4096];
static char g_compressed_path[4096];

static void assert_near(double value, double expected, double tolerance) {
    if (fabs(value - expected) > tolerance) fail_msg("%.6f is not %.6f +- %g", value, expected, tolerance);
}

static void test_binary_frame_header_and_points(void **state) {
    pcd_cloud cloud;
    char error[512] = "";
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    size_t i;
    int axis;
    (void)state;
    if (pcd_read_file(g_binary_path, &cloud, error, sizeof error) != 0) fail_msg("%s", error);
    assert_int_equal(cloud.width, 640);
    assert_int_equal(cloud.height, 480);
    assert_int_equal(cloud.count, 307200);
    assert_int_equal(cloud.finite_count, 271575);
    assert_string_equal(cloud.data_format, "binary");
    /* The header says VIEWPOINT 0 0 0 0 1 0 0 (tx ty tz qw qx qy qz). */
    assert_true(cloud.viewpoint[3] == 0.0 && cloud.viewpoint[4] == 1.0);
    assert_true(cloud.viewpoint[5] == 0.0 && cloud.viewpoint[6] == 0.0);
    for (i = 0; i < cloud.count; ++i) {
        const float *p = &cloud.xyz[3 * i];
        if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2])) continue;
        for (axis = 0; axis < 3; ++axis) {
            if (p[axis] < lo[axis]) lo[axis] = p[axis];
            if (p[axis] > hi[axis]) hi[axis] = p[axis];
        }
    }
    /* The ranges the data README gives, to its three decimals. */
    assert_near(lo[0], -0.910, 6e-4);
    assert_near(hi[0], 0.618, 6e-4);
    assert_near(lo[1], -0.724, 6e-4);
    assert_near(hi[1], 0.322, 6e-4);
    assert_near(lo[2], 0.671, 6e-4);
    assert_near(hi[2], 1.713, 6e-4);
    pcd_free(&cloud);
}

/* The same value, NaN included, bit for bit. */
static int same_float(float a, float b) { return memcmp(&a, &b, sizeof a) == 0; }

static void test_compressed_original_equals_binary(void **state) {
    pcd_cloud compressed, binary;
    char error[512] = "";
    size_t i;
    (void)state;
    if (pcd_read_file(g_compressed_path, &compressed, error, sizeof error) != 0) fail_msg("%s", error);
    if (pcd_read_file(g_binary_path, &binary, error, sizeof error) != 0) fail_msg("%s", error);
    assert_string_equal(compressed.data_format, "binary_compressed");
    assert_int_equal(compressed.width, 640);
    assert_int_equal(compressed.height, 480);
    assert_int_equal(compressed.count, binary.count);
    assert_int_equal(compressed.finite_count, 271575);
    assert_true(compressed.has_viewpoint);
    assert_memory_equal(compressed.viewpoint, binary.viewpoint, sizeof binary.viewpoint);
    for (i = 0; i < 3 * binary.count; ++i)
        if (!same_float(compressed.xyz[i], binary.xyz[i]))
            fail_msg("value %zu: %g (compressed) vs %g (binary)", i, compressed.xyz[i], binary.xyz[i]);
    pcd_free(&compressed);
    pcd_free(&binary);
}

/* Writes text to a new temporary file; returns its path in path. */
static void write_temp_file(const char *text, char *path, size_t size) {
    int fd;
    FILE *file;
    snprintf(path, size, "/tmp/opx-pcd-XXXXXX");
    fd = mkstemp(path);
    assert_true(fd >= 0);
    file = fdopen(fd, "w");
    assert_non_null(file);
    fputs(text, file);
    fclose(file);
}

static void test_small_ascii_file(void **state) {
    /* x is not the first field, and one point has no return. */
    static const char text[] =
        "# .PCD v0.7 - Point Cloud Data file format\n"
        "VERSION 0.7\n"
        "FIELDS intensity x y z rgb\n"
        "SIZE 4 4 4 4 4\n"
        "TYPE F F F F U\n"
        "COUNT 1 1 1 1 1\n"
        "WIDTH 3\n"
        "HEIGHT 1\n"
        "VIEWPOINT 0 0 0 1 0 0 0\n"
        "POINTS 3\n"
        "DATA ascii\n"
        "0.5 1.25 -2 3.5 4278190335\n"
        "7 nan nan nan 0\n"
        "1 0.001 0.002 0.003 16777215\n";
    static const float expected[9] = {1.25f, -2.0f, 3.5f, NAN, NAN, NAN, 0.001f, 0.002f, 0.003f};
    char path[64], error[512] = "";
    pcd_cloud cloud;
    int i;
    (void)state;
    write_temp_file(text, path, sizeof path);
    if (pcd_read_file(path, &cloud, error, sizeof error) != 0) fail_msg("%s", error);
    unlink(path);
    assert_int_equal(cloud.count, 3);
    assert_int_equal(cloud.width, 3);
    assert_int_equal(cloud.height, 1);
    assert_int_equal(cloud.finite_count, 2);
    assert_string_equal(cloud.data_format, "ascii");
    for (i = 0; i < 9; ++i) {
        if (isnan(expected[i])) assert_true(isnan(cloud.xyz[i]));
        else assert_true(cloud.xyz[i] == expected[i]);
    }
    pcd_free(&cloud);
}

static void test_truncated_binary_is_an_error(void **state) {
    static const char text[] =
        "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
        "WIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA binary\n"
        "0123456789ab"; /* one point of the two */
    char path[64], error[512] = "";
    pcd_cloud cloud;
    (void)state;
    write_temp_file(text, path, sizeof path);
    assert_int_equal(pcd_read_file(path, &cloud, error, sizeof error), -1);
    unlink(path);
    assert_non_null(strstr(error, "truncated"));
}

static void test_double_fields_are_read(void **state) {
    static const char text[] =
        "VERSION 0.7\nFIELDS x y z\nSIZE 8 8 8\nTYPE F F F\nCOUNT 1 1 1\n"
        "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2.5 -3\n";
    char path[64], error[512] = "";
    pcd_cloud cloud;
    (void)state;
    write_temp_file(text, path, sizeof path);
    assert_int_equal(pcd_read_file(path, &cloud, error, sizeof error), 0);
    unlink(path);
    assert_int_equal(cloud.count, 1);
    assert_true(cloud.xyz[0] == 1.0f && cloud.xyz[1] == 2.5f && cloud.xyz[2] == -3.0f);
    pcd_free(&cloud);
}

static void test_integer_fields_are_rejected(void **state) {
    static const char text[] =
        "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE I I I\nCOUNT 1 1 1\n"
        "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 2 3\n";
    char path[64], error[512] = "";
    pcd_cloud cloud;
    (void)state;
    write_temp_file(text, path, sizeof path);
    assert_int_equal(pcd_read_file(path, &cloud, error, sizeof error), CLOUD_ERROR_UNSUPPORTED);
    unlink(path);
    assert_non_null(strstr(error, "float32 or float64"));
}

static void test_missing_file_is_an_error(void **state) {
    char error[512] = "";
    pcd_cloud cloud;
    (void)state;
    assert_int_equal(pcd_read_file("/nonexistent/frame.pcd", &cloud, error, sizeof error), CLOUD_ERROR_IO);
    assert_non_null(strstr(error, "/nonexistent/frame.pcd"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_binary_frame_header_and_points),
        cmocka_unit_test(test_compressed_original_equals_binary),
        cmocka_unit_test(test_small_ascii_file),
        cmocka_unit_test(test_truncated_binary_is_an_error),
        cmocka_unit_test(test_double_fields_are_read),
        cmocka_unit_test(test_integer_fields_are_rejected),
        cmocka_unit_test(test_missing_file_is_an_error),
    };
    require_data_file(FRAME_STEM "_binary.pcd", g_binary_path, sizeof g_binary_path);
    require_data_file(FRAME_STEM ".pcd", g_compressed_path, sizeof g_compressed_path);
    return cmocka_run_group_tests_name("real_pcd_reader", tests, NULL, NULL);
}
