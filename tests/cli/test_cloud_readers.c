/*
 * cloud_readers: the PCD and PLY readers of the octoprox tool on small and
 * hostile files written here: sizes that overflow, counts far beyond what
 * the file holds, numbers that are not numbers, overlong lines and words,
 * repeated fields, skipped elements without properties, and clouds
 * streamed through a pipe (no file size to bound them).  Every bad file is
 * a clean error with a message, read quickly, with nothing allocated for
 * the points it only announces.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "fifo_file.h"
#include "pcd_reader.h"
#include "ply_reader.h"

#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

#define XYZ_FIELDS "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
#define PLY_XYZ "property float x\nproperty float y\nproperty float z\n"

/* Points streamed through a pipe: more than the readers' first slice. */
#define STREAMED_POINTS 70000

static char g_buffer[1 << 21];

static void expect_pcd_error(const char *name, const void *bytes, size_t size, const char *message) {
    pcd_cloud cloud;
    char error[600] = "";
    const char *path = write_bytes(name, bytes, size);
    if (pcd_read_file(path, &cloud, error, sizeof error) == 0) fail_msg("%s was read (%zu points)", name, cloud.count);
    if (strstr(error, message) == NULL) fail_msg("%s: \"%s\" lacks \"%s\"", name, error, message);
    assert_null(cloud.xyz);
    assert_int_equal(cloud.count, 0);
}

static void expect_pcd_text_error(const char *name, const char *text, const char *message) {
    expect_pcd_error(name, text, strlen(text), message);
}

static void expect_ply_error(const char *name, const void *bytes, size_t size, const char *message) {
    ply_cloud cloud;
    char error[600] = "";
    const char *path = write_bytes(name, bytes, size);
    if (ply_read_file(path, &cloud, error, sizeof error) == 0) fail_msg("%s was read (%zu points)", name, cloud.count);
    if (strstr(error, message) == NULL) fail_msg("%s: \"%s\" lacks \"%s\"", name, error, message);
    assert_null(cloud.xyz);
    assert_int_equal(cloud.count, 0);
}

static void expect_ply_text_error(const char *name, const char *text, const char *message) {
    expect_ply_error(name, text, strlen(text), message);
}

/* header, then `count` binary float32 points (i, -i, 0.5 i). */
static size_t binary_cloud(const char *header, size_t count) {
    size_t n = strlen(header), i;
    memcpy(g_buffer, header, n);
    for (i = 0; i < count; ++i) {
        const float p[3] = {(float)i, -(float)i, 0.5f * (float)i};
        memcpy(g_buffer + n, p, sizeof p);
        n += sizeof p;
    }
    return n;
}

static void assert_streamed_point(const float *xyz, size_t i) {
    assert_true(xyz[3 * i] == (float)i && xyz[3 * i + 1] == -(float)i && xyz[3 * i + 2] == 0.5f * (float)i);
}

/* ---- PCD ---- */

static void a_pcd_whose_width_wraps_the_allocation_is_refused(void **state) {
    (void)state;
    /* WIDTH 2^62: WIDTH * 3 * sizeof(float) wraps to 0 in 64 bits. */
    expect_pcd_text_error("wrap.pcd", XYZ_FIELDS "WIDTH 4611686018427387904\nDATA ascii\n1 2 3\n", "WIDTH");
}

static void a_pcd_whose_width_times_height_overflows_is_refused(void **state) {
    (void)state;
    expect_pcd_text_error("product.pcd",
                          XYZ_FIELDS "WIDTH 4294967296\nHEIGHT 4294967296\nPOINTS 0\nDATA ascii\n1 2 3\n", "WIDTH");
    /* The largest WIDTH and HEIGHT: their product fits 64 bits but no memory. */
    expect_pcd_text_error("largest.pcd", XYZ_FIELDS "WIDTH 4294967295\nHEIGHT 4294967295\nDATA ascii\n1 2 3\n",
                          "more than this machine can hold");
}

static void a_pcd_announcing_more_points_than_its_bytes_is_truncated(void **state) {
    (void)state;
    expect_pcd_error("binary_many.pcd", g_buffer,
                     binary_cloud(XYZ_FIELDS "WIDTH 4294967295\nHEIGHT 1000\nDATA binary\n", 2),
                     "binary data truncated: the header announces 4294967295000 points");
    expect_pcd_text_error("ascii_many.pcd", XYZ_FIELDS "WIDTH 1000000\nDATA ascii\n1 2 3\n4 5 6\n",
                          "ascii data truncated: the header announces 1000000 points");
    /* Three values need five bytes at least: "1 2 " is one byte short. */
    expect_pcd_text_error("ascii_short.pcd", XYZ_FIELDS "WIDTH 1\nDATA ascii\n1 2 ", "truncated");
}

static void pcd_header_numbers_must_be_whole_and_in_range(void **state) {
    static const struct { const char *lines, *message; } cases[] = {
        {XYZ_FIELDS "WIDTH -1\n", "WIDTH \"-1\""},
        {XYZ_FIELDS "WIDTH +3\n", "WIDTH \"+3\""},
        {XYZ_FIELDS "WIDTH 3x\n", "WIDTH \"3x\""},
        {XYZ_FIELDS "WIDTH 0\n", "WIDTH \"0\""},
        {XYZ_FIELDS "WIDTH 1\nHEIGHT 0\n", "HEIGHT \"0\""},
        {XYZ_FIELDS "WIDTH 1\nHEIGHT 18446744073709551617\n", "HEIGHT"},
        {XYZ_FIELDS "WIDTH 1\nPOINTS 99999999999999999999999\n", "POINTS"},
        {XYZ_FIELDS "WIDTH 2\nHEIGHT 3\nPOINTS 5\n", "POINTS 5 is not WIDTH * HEIGHT = 6"},
        {XYZ_FIELDS "WIDTH\n", "WIDTH needs 1 value, not 0"},
        {XYZ_FIELDS "WIDTH 1 2\n", "WIDTH needs 1 value, not 2"},
        {XYZ_FIELDS "WIDTH 1\nVIEWPOINT 0 0 0 1 0 0 zero\n", "VIEWPOINT entry \"zero\""},
        {XYZ_FIELDS "WIDTH 1\nVIEWPOINT 0 0 0 1 0 0\n", "VIEWPOINT needs 7 values"},
        {"FIELDS x y z\nSIZE 4 4 four\n", "SIZE entry \"four\""},
        {"FIELDS x y z\nSIZE 4 4 -4\n", "SIZE entry \"-4\""},
        {"FIELDS x y z\nSIZE 4 4 16\n", "SIZE entry \"16\""},
        {"FIELDS x y z\nSIZE 4 4\n", "SIZE has 2 entries, but FIELDS names 3"},
        {"SIZE 4 4 4\nFIELDS x y z\n", "SIZE has 3 entries, but FIELDS names 0"},
        {"FIELDS x y z\nCOUNT 1 1 0\n", "COUNT entry \"0\""},
        {"FIELDS x y z\nCOUNT 1 1 65537\n", "COUNT entry \"65537\""},
        {"FIELDS x y z\nCOUNT 1 1 4294967297\n", "COUNT entry \"4294967297\""},
        {"FIELDS x y z\nTYPE F F Q\n", "TYPE entry \"Q\""},
        {"FIELDS x y z\nTYPE F F FF\n", "TYPE entry \"FF\""},
        {"FIELDS x y z i\nSIZE 4 4 4 3\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 1\n", "SIZE 3"},
    };
    char text[1024];
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        snprintf(text, sizeof text, "%sDATA ascii\n1 2 3 4\n", cases[i].lines);
        expect_pcd_text_error("numbers.pcd", text, cases[i].message);
    }
}

static void a_pcd_naming_x_twice_is_refused(void **state) {
    (void)state;
    /* The second x, one byte at the end of a 13-byte point, would be read
     * as 4 bytes past the point. */
    expect_pcd_text_error("twice.pcd",
                          "FIELDS x y z x\nSIZE 4 4 4 1\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 1\nDATA binary\n"
                          "0123456789abc",
                          "field \"x\" appears twice");
}

static void repeated_padding_fields_are_skipped(void **state) {
    static const char header[] = "FIELDS x _ y z _\nSIZE 4 1 4 4 1\nTYPE F U F F U\nCOUNT 1 1 1 1 1\n"
                                 "WIDTH 2\nDATA binary\n";
    const float points[2][3] = {{1.0f, 2.0f, 3.0f}, {-4.0f, 5.5f, 6.0f}};
    pcd_cloud cloud;
    char error[600] = "";
    size_t n = strlen(header), i;
    (void)state;
    memcpy(g_buffer, header, n);
    for (i = 0; i < 2; ++i) {
        memcpy(g_buffer + n, &points[i][0], 4);
        g_buffer[n + 4] = 'p';
        memcpy(g_buffer + n + 5, &points[i][1], 8);
        g_buffer[n + 13] = 'q';
        n += 14;
    }
    if (pcd_read_file(write_bytes("padding.pcd", g_buffer, n), &cloud, error, sizeof error) != 0)
        fail_msg("%s", error);
    assert_int_equal(cloud.count, 2);
    assert_memory_equal(cloud.xyz, points, sizeof points);
    pcd_free(&cloud);
}

static void pcd_fields_lines_and_words_are_bounded(void **state) {
    static char text[8192];
    size_t n;
    int i;
    (void)state;
    n = (size_t)snprintf(text, sizeof text, "FIELDS x y z");
    for (i = 0; i < 30; ++i) n += (size_t)snprintf(text + n, sizeof text - n, " f%d", i);
    snprintf(text + n, sizeof text - n, "\nDATA ascii\n");
    expect_pcd_text_error("wide.pcd", text, "FIELDS must name 1 to 32 fields");

    n = (size_t)snprintf(text, sizeof text, "# ");
    memset(text + n, 'c', 5000);
    snprintf(text + n + 5000, sizeof text - n - 5000, "\n" XYZ_FIELDS "WIDTH 1\nDATA ascii\n1 2 3\n");
    expect_pcd_text_error("longline.pcd", text, "a header line is longer than");

    n = (size_t)snprintf(text, sizeof text, XYZ_FIELDS "WIDTH 1\nDATA ascii\n1 2 ");
    memset(text + n, '7', 200);
    snprintf(text + n + 200, sizeof text - n - 200, "\n");
    expect_pcd_text_error("longword.pcd", text, "longer than 127 characters");
}

static void a_binary_pcd_streams_through_a_pipe(void **state) {
    static char header[256];
    pcd_cloud cloud;
    char error[600] = "";
    pid_t writer;
    size_t size;
    const char *path;
    (void)state;
    snprintf(header, sizeof header, XYZ_FIELDS "WIDTH %d\nHEIGHT 1\nDATA binary\n", STREAMED_POINTS);
    size = binary_cloud(header, STREAMED_POINTS);
    path = serve_through_fifo("stream.pcd", g_buffer, size, &writer);
    if (pcd_read_file(path, &cloud, error, sizeof error) != 0) fail_msg("%s", error);
    finish_fifo(writer);
    assert_int_equal(cloud.count, STREAMED_POINTS);
    assert_int_equal(cloud.finite_count, STREAMED_POINTS);
    assert_streamed_point(cloud.xyz, 0);
    assert_streamed_point(cloud.xyz, STREAMED_POINTS - 1);
    pcd_free(&cloud);

    /* Four billion points announced, two sent: truncated, not allocated. */
    size = binary_cloud(XYZ_FIELDS "WIDTH 4000000000\nHEIGHT 1\nDATA binary\n", 2);
    path = serve_through_fifo("stream_short.pcd", g_buffer, size, &writer);
    assert_int_equal(pcd_read_file(path, &cloud, error, sizeof error), -1);
    finish_fifo(writer);
    assert_non_null(strstr(error, "binary data truncated at point 2 of 4000000000"));
}

/* ---- PLY ---- */

static void a_ply_skips_a_huge_element_without_properties_at_once(void **state) {
    static const char text[] = "ply\nformat ascii 1.0\nelement a 1000000000000000000\nelement vertex 1\n" PLY_XYZ
                               "end_header\n1 2 3\n";
    ply_cloud cloud;
    char error[600] = "";
    (void)state;
    assert_int_equal(sizeof text - 1, 136);
    if (ply_read_file(write_text("empty_rows.ply", text), &cloud, error, sizeof error) != 0) fail_msg("%s", error);
    assert_int_equal(cloud.count, 1);
    assert_true(cloud.xyz[0] == 1.0f && cloud.xyz[1] == 2.0f && cloud.xyz[2] == 3.0f);
    ply_free(&cloud);
}

static void a_ply_announcing_more_rows_than_its_bytes_is_truncated(void **state) {
    static char binary[512];
    size_t n;
    (void)state;
    expect_ply_text_error("huge_skip.ply",
                          "ply\nformat ascii 1.0\nelement a 1000000000000000000\nproperty uchar v\n"
                          "element vertex 1\n" PLY_XYZ "end_header\n1\n1 2 3\n",
                          "element \"a\" announces 1000000000000000000 rows");
    expect_ply_text_error("huge_vertices.ply",
                          "ply\nformat ascii 1.0\nelement vertex 1000000000000\n" PLY_XYZ "end_header\n1 2 3\n",
                          "element \"vertex\" announces 1000000000000 rows");
    n = (size_t)snprintf(binary, sizeof binary, "ply\nformat binary_little_endian 1.0\nelement vertex "
                         "1000000000000000\n" PLY_XYZ "end_header\n");
    memset(binary + n, 0, 12);
    expect_ply_error("huge_binary.ply", binary, n + 12, "the 12 bytes left hold at most 1");
    /* A list row takes its count's byte at least, even when empty. */
    n = (size_t)snprintf(binary, sizeof binary, "ply\nformat binary_little_endian 1.0\nelement face 100\n"
                         "property list uchar int v\nelement vertex 1\n" PLY_XYZ "end_header\n");
    memset(binary + n, 0, 50);
    expect_ply_error("huge_lists.ply", binary, n + 50, "element \"face\" announces 100 rows");
}

static void ply_counts_must_be_whole_numbers(void **state) {
    static const char *const counts[] = {"-1", "+1", "1e3", "0x10", "99999999999999999999", "18446744073709551615"};
    char text[512];
    size_t i;
    (void)state;
    for (i = 0; i < sizeof counts / sizeof counts[0]; ++i) {
        snprintf(text, sizeof text, "ply\nformat ascii 1.0\nelement vertex %s\n" PLY_XYZ "end_header\n1 2 3\n",
                 counts[i]);
        expect_ply_text_error("count.ply", text, "bad count");
    }
}

static void ply_lines_words_and_lists_are_bounded(void **state) {
    static char text[8192];
    static const unsigned char list_row[] = {200, 1, 0, 0, 0};
    size_t n;
    (void)state;
    n = (size_t)snprintf(text, sizeof text, "ply\nformat ascii 1.0\ncomment ");
    memset(text + n, 'c', 3000);
    snprintf(text + n + 3000, sizeof text - n - 3000, "\nelement vertex 1\n" PLY_XYZ "end_header\n1 2 3\n");
    expect_ply_text_error("longline.ply", text, "a header line is longer than");

    n = (size_t)snprintf(text, sizeof text, "ply\nformat ascii 1.0\nelement vertex 1\n" PLY_XYZ "end_header\n1 2 ");
    memset(text + n, '7', 100);
    text[n + 100] = '\0';
    expect_ply_text_error("longword.ply", text, "not a number");

    /* A list of 200 ints that holds one. */
    n = (size_t)snprintf(text, sizeof text, "ply\nformat binary_little_endian 1.0\nelement face 1\n"
                         "property list uchar int v\nelement vertex 1\n" PLY_XYZ "end_header\n");
    memcpy(text + n, list_row, sizeof list_row);
    expect_ply_error("shortlist.ply", text, n + sizeof list_row, "data truncated in element \"face\" at row 0");
}

static void a_binary_ply_skips_faces_and_streams_through_a_pipe(void **state) {
    static const unsigned char face[] = {3, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0};
    static char header[512];
    ply_cloud cloud;
    char error[600] = "";
    pid_t writer;
    size_t n;
    const char *path;
    (void)state;
    snprintf(header, sizeof header, "ply\nformat binary_little_endian 1.0\nelement face 1\n"
             "property list uchar int vertex_indices\nelement vertex %d\n" PLY_XYZ "end_header\n", STREAMED_POINTS);
    n = strlen(header);
    memcpy(g_buffer, header, n);
    memcpy(g_buffer + n, face, sizeof face);
    n += sizeof face;
    {
        size_t i;
        for (i = 0; i < STREAMED_POINTS; ++i) {
            const float p[3] = {(float)i, -(float)i, 0.5f * (float)i};
            memcpy(g_buffer + n, p, sizeof p);
            n += sizeof p;
        }
    }
    path = serve_through_fifo("stream.ply", g_buffer, n, &writer);
    if (ply_read_file(path, &cloud, error, sizeof error) != 0) fail_msg("%s", error);
    finish_fifo(writer);
    assert_int_equal(cloud.count, STREAMED_POINTS);
    assert_streamed_point(cloud.xyz, 1);
    assert_streamed_point(cloud.xyz, STREAMED_POINTS - 1);
    ply_free(&cloud);
    if (ply_read_file(write_bytes("faces.ply", g_buffer, n), &cloud, error, sizeof error) != 0) fail_msg("%s", error);
    assert_int_equal(cloud.count, STREAMED_POINTS);
    assert_streamed_point(cloud.xyz, STREAMED_POINTS - 1);
    ply_free(&cloud);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_pcd_whose_width_wraps_the_allocation_is_refused),
        cmocka_unit_test(a_pcd_whose_width_times_height_overflows_is_refused),
        cmocka_unit_test(a_pcd_announcing_more_points_than_its_bytes_is_truncated),
        cmocka_unit_test(pcd_header_numbers_must_be_whole_and_in_range),
        cmocka_unit_test(a_pcd_naming_x_twice_is_refused),
        cmocka_unit_test(repeated_padding_fields_are_skipped),
        cmocka_unit_test(pcd_fields_lines_and_words_are_bounded),
        cmocka_unit_test(a_binary_pcd_streams_through_a_pipe),
        cmocka_unit_test(a_ply_skips_a_huge_element_without_properties_at_once),
        cmocka_unit_test(a_ply_announcing_more_rows_than_its_bytes_is_truncated),
        cmocka_unit_test(ply_counts_must_be_whole_numbers),
        cmocka_unit_test(ply_lines_words_and_lists_are_bounded),
        cmocka_unit_test(a_binary_ply_skips_faces_and_streams_through_a_pipe),
    };
    /* A reader that loops over an announced count instead of the file's
     * bytes hangs: the alarm turns that into a failure. */
    alarm(60);
    return cmocka_run_group_tests_name("cloud_readers", tests, NULL, NULL);
}
