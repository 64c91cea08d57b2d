/*
 * cloud_readers_lzf: PCD files with DATA binary_compressed, written here
 * as PCL lays them out (the compressed size and the decompressed size as
 * two little-endian uint32, then the LZF block of the fields one after
 * another: all x, then all y, ...).  Good files read as their points;
 * files whose sizes lie, whose block is cut short or whose LZF data is
 * corrupt are clean errors with a message, never a crash or an allocation
 * of what they only announce.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "fifo_file.h"
#include "pcd_reader.h"

#include <lzf.h>

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#define XYZ_RGB "FIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
#define MAX_POINTS 70000 /* more than a pipe's first slice of compressed bytes */

static unsigned char g_soa[MAX_POINTS * 16 + 64];
static unsigned char g_file[MAX_POINTS * 32 + 1024];

/* The i-th test point: (i, -2i, 0.25i), NaN for every seventh. */
static void test_point(size_t i, float p[3]) {
    const float nan = NAN;
    p[0] = i % 7 == 3 ? nan : (float)i;
    p[1] = i % 7 == 3 ? nan : -2.0f * (float)i;
    p[2] = i % 7 == 3 ? nan : 0.25f * (float)i;
}

/* The fields x y z rgb of `count` test points, field after field. */
static uint32_t xyz_rgb_fields(size_t count) {
    size_t i;
    for (i = 0; i < count; ++i) {
        float p[3];
        const uint32_t rgb = 0xff000000u | (uint32_t)i;
        test_point(i, p);
        memcpy(g_soa + 4 * i, &p[0], 4);
        memcpy(g_soa + 4 * (count + i), &p[1], 4);
        memcpy(g_soa + 4 * (2 * count + i), &p[2], 4);
        memcpy(g_soa + 4 * (3 * count + i), &rgb, 4);
    }
    return (uint32_t)(16 * count);
}

static void put_le32(unsigned char *at, uint32_t v) {
    at[0] = (unsigned char)v, at[1] = (unsigned char)(v >> 8), at[2] = (unsigned char)(v >> 16);
    at[3] = (unsigned char)(v >> 24);
}

/* header, then the sizes and the block of `fields` (fields_size bytes)
 * compressed; `announced` is the decompressed size written (0: the true
 * one).  Returns the file's size in g_file. */
static size_t compressed_file(const char *header, const void *fields, uint32_t fields_size, uint32_t announced) {
    const size_t n = strlen(header);
    const unsigned int packed = lzf_compress(fields, fields_size, g_file + n + 8, sizeof g_file - n - 8);
    if (packed == 0) fail_msg("lzf_compress of %u bytes failed", fields_size);
    memcpy(g_file, header, n);
    put_le32(g_file + n, packed);
    put_le32(g_file + n + 4, announced ? announced : fields_size);
    return n + 8 + packed;
}

static void assert_test_points(const pcd_cloud *cloud, size_t count) {
    size_t i;
    int axis;
    assert_int_equal(cloud->count, count);
    for (i = 0; i < count; ++i) {
        float p[3];
        test_point(i, p);
        for (axis = 0; axis < 3; ++axis)
            if (memcmp(&p[axis], &cloud->xyz[3 * i + (size_t)axis], sizeof(float)) != 0)
                fail_msg("point %zu axis %d: %g, not %g", i, axis, cloud->xyz[3 * i + (size_t)axis], p[axis]);
    }
}

static void expect_error(const char *name, size_t size, const char *message) {
    pcd_cloud cloud;
    char error[600] = "";
    const char *path = write_bytes(name, g_file, size);
    const int status = pcd_read_file(path, &cloud, error, sizeof error);
    if (status == 0) fail_msg("%s was read (%zu points)", name, cloud.count);
    assert_int_equal(status, CLOUD_ERROR_CORRUPT);
    if (strstr(error, message) == NULL) fail_msg("%s: \"%s\" lacks \"%s\"", name, error, message);
    assert_null(cloud.xyz);
    assert_int_equal(cloud.count, 0);
}

static void an_organized_compressed_pcd_is_read(void **state) {
    const char *header = "VERSION 0.7\n" XYZ_RGB "WIDTH 5\nHEIGHT 4\nVIEWPOINT 1 2 3 0 1 0 0\nPOINTS 20\n"
                         "DATA binary_compressed\n";
    size_t size = compressed_file(header, g_soa, xyz_rgb_fields(20), 0);
    pcd_cloud cloud;
    char error[600] = "";
    (void)state;
    /* PCL may leave bytes after the block: they are ignored. */
    memset(g_file + size, 0xab, 100);
    if (pcd_read_file(write_bytes("organized.pcd", g_file, size + 100), &cloud, error, sizeof error) != 0)
        fail_msg("%s", error);
    assert_string_equal(cloud.data_format, "binary_compressed");
    assert_int_equal(cloud.width, 5);
    assert_int_equal(cloud.height, 4);
    assert_int_equal(cloud.finite_count, 17);
    assert_true(cloud.has_viewpoint && cloud.viewpoint[0] == 1.0 && cloud.viewpoint[4] == 1.0);
    assert_test_points(&cloud, 20);
    pcd_free(&cloud);
}

/* x y z as float64 behind a 2-byte field, each in its own block. */
static void float64_fields_after_others_are_read(void **state) {
    static const double xyz[3][3] = {{1.5, -2.25, 1e-3}, {4.0, 5.0, 6.0}, {-7.0, 8.5, 9.25}};
    unsigned char fields[3 * 2 + 3 * 3 * 8];
    pcd_cloud cloud;
    char error[600] = "";
    size_t i, size;
    int axis;
    (void)state;
    memset(fields, 0x11, 6); /* intensity: all three points */
    for (axis = 0; axis < 3; ++axis)
        for (i = 0; i < 3; ++i) memcpy(fields + 6 + 8 * (3 * (size_t)axis + i), &xyz[i][axis], 8);
    size = compressed_file("FIELDS intensity x y z\nSIZE 2 8 8 8\nTYPE U F F F\nCOUNT 1 1 1 1\nWIDTH 3\n"
                           "DATA binary_compressed\n", fields, sizeof fields, 0);
    if (pcd_read_file(write_bytes("doubles.pcd", g_file, size), &cloud, error, sizeof error) != 0)
        fail_msg("%s", error);
    assert_int_equal(cloud.count, 3);
    assert_false(cloud.has_viewpoint);
    for (i = 0; i < 3; ++i)
        for (axis = 0; axis < 3; ++axis) assert_true(cloud.xyz[3 * i + (size_t)axis] == (float)xyz[i][axis]);
    pcd_free(&cloud);
}

static void a_compressed_pcd_streams_through_a_pipe(void **state) {
    static char header[256];
    pcd_cloud cloud;
    char error[600] = "";
    pid_t writer;
    size_t size;
    const char *path;
    (void)state;
    snprintf(header, sizeof header, XYZ_RGB "WIDTH %d\nDATA binary_compressed\n", MAX_POINTS);
    size = compressed_file(header, g_soa, xyz_rgb_fields(MAX_POINTS), 0);
    path = serve_through_fifo("stream.pcd", g_file, size, &writer);
    if (pcd_read_file(path, &cloud, error, sizeof error) != 0) fail_msg("%s", error);
    finish_fifo(writer);
    assert_test_points(&cloud, MAX_POINTS);
    pcd_free(&cloud);

    /* A block announced at 4 GB - 1 on a pipe that brings a few bytes. */
    size = compressed_file(header, g_soa, xyz_rgb_fields(MAX_POINTS), 0);
    put_le32(g_file + strlen(header), UINT32_MAX);
    path = serve_through_fifo("stream_short.pcd", g_file, strlen(header) + 100, &writer);
    assert_int_equal(pcd_read_file(path, &cloud, error, sizeof error), CLOUD_ERROR_CORRUPT);
    finish_fifo(writer);
    assert_non_null(strstr(error, "truncated"));
    assert_null(cloud.xyz);
}

static void compressed_sizes_that_lie_are_refused(void **state) {
    const char *header = XYZ_RGB "WIDTH 100\nDATA binary_compressed\n";
    const size_t n = strlen(header);
    size_t size;
    (void)state;
    size = compressed_file(header, g_soa, xyz_rgb_fields(100), 0);
    expect_error("no_sizes.pcd", n + 3, "3 of the 8 bytes of its two sizes");
    expect_error("cut_block.pcd", size - 10, "truncated: a block of");
    put_le32(g_file + n, UINT32_MAX);
    expect_error("packed_too_big.pcd", size, "truncated: a block of 4294967295 bytes");
    compressed_file(header, g_soa, xyz_rgb_fields(100), 1600 + 16);
    expect_error("unpacked_not_points.pcd", size, "decompresses to 1616 bytes, not POINTS x point size = 100 x 16");
    /* 4 bytes cannot stand for 1600. */
    compressed_file(header, g_soa, xyz_rgb_fields(100), 0);
    put_le32(g_file + n, 4);
    expect_error("ratio.pcd", size, "4 bytes of LZF data cannot decompress to 1600 bytes");
    /* A width whose block would pass 4 GB. */
    compressed_file(XYZ_RGB "WIDTH 4000000000\nDATA binary_compressed\n", g_soa, 16, 0);
    expect_error("huge.pcd", strlen(XYZ_RGB "WIDTH 4000000000\nDATA binary_compressed\n") + 8 + 20, "decompresses to 16");
}

static void corrupt_lzf_data_is_refused(void **state) {
    const char *header = XYZ_RGB "WIDTH 100\nDATA binary_compressed\n";
    const size_t n = strlen(header);
    size_t size, i;
    (void)state;
    /* Data of 12 bytes less than the header's points. */
    size = compressed_file(header, g_soa, xyz_rgb_fields(100) - 12, 1600);
    expect_error("short_data.pcd", size, "decompresses to 1588 bytes, not the 1600");
    /* Data of more bytes than the header's points. */
    xyz_rgb_fields(101);
    size = compressed_file(header, g_soa, 1616, 1600);
    expect_error("long_data.pcd", size, "more than the 1600 bytes");
    /* A back reference before the start of the output. */
    size = compressed_file(header, g_soa, xyz_rgb_fields(100), 0);
    g_file[n + 8] = 0xe0;
    g_file[n + 9] = 0xff;
    g_file[n + 10] = 0xff;
    expect_error("reference.pcd", size, "corrupt LZF data");
    /* Every byte of a good block flipped in turn: an error or points, never a crash. */
    size = compressed_file(header, g_soa, xyz_rgb_fields(100), 0);
    for (i = n + 8; i < size; ++i) {
        pcd_cloud cloud;
        char error[600];
        g_file[i] ^= 0x5a;
        if (pcd_read_file(write_bytes("flipped.pcd", g_file, size), &cloud, error, sizeof error) == 0)
            pcd_free(&cloud);
        else
            assert_null(cloud.xyz);
        g_file[i] ^= 0x5a;
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(an_organized_compressed_pcd_is_read),
        cmocka_unit_test(float64_fields_after_others_are_read),
        cmocka_unit_test(a_compressed_pcd_streams_through_a_pipe),
        cmocka_unit_test(compressed_sizes_that_lie_are_refused),
        cmocka_unit_test(corrupt_lzf_data_is_refused),
    };
    alarm(60);
    return cmocka_run_group_tests_name("cloud_readers_lzf", tests, NULL, NULL);
}
