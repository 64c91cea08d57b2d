/*
 * opx_point_cloud_*: PCD (ascii, binary_compressed) and PLY files read
 * through the library, their info (format, encoding, organized size,
 * VIEWPOINT in ROS order), points copied packed or strided, buffers too
 * small, and bad arguments and files: a status and a message naming the
 * function and the argument or the file.  Files are written in the
 * working directory (ctest: the build directory).
 */
#define _POSIX_C_SOURCE 200809L
#include "opx_test.h"

#include <unistd.h>

#define NOT_NULL_SENTINEL ((opx_point_cloud *)(uintptr_t)0x10)

static const char kAsciiPcd[] =
    "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
    "WIDTH 2\nHEIGHT 2\nVIEWPOINT 1 2 3 0.5 -0.5 0.5 -0.5\nPOINTS 4\nDATA ascii\n"
    "1 2 3 0\n4 5 6 0\nnan nan nan 0\n-1 -2.5 0.125 0\n";
static const float kAsciiPoints[12] = {1, 2, 3, 4, 5, 6, NAN, NAN, NAN, -1, -2.5f, 0.125f};

static const char *write_file(const char *name, const void *bytes, size_t size) {
    FILE *f = fopen(name, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(bytes, 1, size, f), size);
    assert_int_equal(fclose(f), 0);
    return name;
}

static const char *write_text(const char *name, const char *text) { return write_file(name, text, strlen(text)); }

static opx_point_cloud *read_ok(const char *path) {
    opx_point_cloud *cloud = NULL;
    assert_ok(opx_point_cloud_read_file(path, &cloud));
    assert_non_null(cloud);
    return cloud;
}

static opx_point_cloud_info info_of(const opx_point_cloud *cloud) {
    opx_point_cloud_info info = OPX_POINT_CLOUD_INFO_INIT;
    assert_ok(opx_point_cloud_get_info(cloud, &info));
    return info;
}

static void assert_same_float(float actual, float expected) {
    if (isnan(expected)) assert_true(isnan(actual));
    else assert_true(actual == expected);
}

static void an_organized_ascii_pcd_and_its_viewpoint(void **state) {
    opx_point_cloud *cloud = read_ok(write_text("opx_cloud_ascii.pcd", kAsciiPcd));
    const opx_point_cloud_info info = info_of(cloud);
    float xyz[12];
    size_t count = 0, i;
    (void)state;
    assert_int_equal(info.format, OPX_CLOUD_FORMAT_PCD);
    assert_int_equal(info.encoding, OPX_CLOUD_ENCODING_ASCII);
    assert_int_equal(info.point_count, 4);
    assert_int_equal(info.finite_count, 3);
    assert_int_equal(info.width, 2);
    assert_int_equal(info.height, 2);
    assert_int_equal(info.has_viewpoint, 1);
    /* tx ty tz qw qx qy qz in the file; x y z qx qy qz qw here. */
    assert_true(info.viewpoint.position[0] == 1.0 && info.viewpoint.position[2] == 3.0);
    assert_true(info.viewpoint.orientation[0] == -0.5 && info.viewpoint.orientation[1] == 0.5);
    assert_true(info.viewpoint.orientation[2] == -0.5 && info.viewpoint.orientation[3] == 0.5);
    assert_ok(opx_point_cloud_get_points(cloud, xyz, 4, 0, &count));
    assert_int_equal(count, 4);
    for (i = 0; i < 12; ++i) assert_same_float(xyz[i], kAsciiPoints[i]);
    opx_point_cloud_destroy(cloud);
}

static void points_go_to_a_strided_buffer(void **state) {
    opx_point_cloud *cloud = read_ok(write_text("opx_cloud_strided.pcd", kAsciiPcd));
    float xyzw[16];
    size_t count = 0, i;
    (void)state;
    for (i = 0; i < 16; ++i) xyzw[i] = 42.0f;
    assert_ok(opx_point_cloud_get_points(cloud, xyzw, 4, 4 * sizeof(float), &count));
    for (i = 0; i < 4; ++i) {
        assert_same_float(xyzw[4 * i], kAsciiPoints[3 * i]);
        assert_same_float(xyzw[4 * i + 2], kAsciiPoints[3 * i + 2]);
        assert_true(xyzw[4 * i + 3] == 42.0f);
    }
    opx_point_cloud_destroy(cloud);
}

static void a_small_buffer_gets_the_count_and_nothing_else(void **state) {
    opx_point_cloud *cloud = read_ok(write_text("opx_cloud_small.pcd", kAsciiPcd));
    float xyz[9] = {7, 7, 7, 7, 7, 7, 7, 7, 7};
    size_t count = 0, i;
    (void)state;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, "opx_point_cloud_get_points", "capacity 3",
                   opx_point_cloud_get_points(cloud, xyz, 3, 0, &count));
    assert_int_equal(count, 4);
    for (i = 0; i < 9; ++i) assert_true(xyz[i] == 7.0f);
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, "opx_point_cloud_get_points", "capacity 0",
                   opx_point_cloud_get_points(cloud, NULL, 0, 0, &count));
    assert_int_equal(count, 4);
    opx_point_cloud_destroy(cloud);
}

/* A binary_compressed PCD whose LZF block is one literal run (a control
 * byte of length - 1, then the bytes): x x, y y, z z of two points. */
static void a_compressed_pcd(void **state) {
    static const char header[] = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 1\n"
                                 "DATA binary_compressed\n";
    const float fields[6] = {1.0f, 4.0f, 2.0f, 5.0f, 3.0f, 6.0f};
    unsigned char file[256];
    const size_t n = strlen(header);
    const uint32_t packed = 1 + sizeof fields, unpacked = sizeof fields;
    opx_point_cloud *cloud;
    opx_point_cloud_info info;
    float xyz[6];
    size_t count = 0;
    (void)state;
    memcpy(file, header, n);
    memcpy(file + n, &packed, 4); /* little-endian, as on every machine this runs on */
    memcpy(file + n + 4, &unpacked, 4);
    file[n + 8] = (unsigned char)(sizeof fields - 1);
    memcpy(file + n + 9, fields, sizeof fields);
    cloud = read_ok(write_file("opx_cloud_lzf.pcd", file, n + 9 + sizeof fields));
    info = info_of(cloud);
    assert_int_equal(info.encoding, OPX_CLOUD_ENCODING_BINARY_COMPRESSED);
    assert_int_equal(info.has_viewpoint, 0);
    assert_true(info.viewpoint.orientation[3] == 1.0);
    assert_ok(opx_point_cloud_get_points(cloud, xyz, 2, 0, &count));
    assert_true(xyz[0] == 1.0f && xyz[1] == 2.0f && xyz[2] == 3.0f && xyz[3] == 4.0f && xyz[5] == 6.0f);
    opx_point_cloud_destroy(cloud);
    /* The same block announced as 4 bytes longer: corrupt, named. */
    memcpy(file + n + 4, &(uint32_t){unpacked + 4}, 4);
    write_file("opx_cloud_lzf_lying.pcd", file, n + 9 + sizeof fields);
    cloud = NOT_NULL_SENTINEL;
    expect_failure(OPX_ERROR_CORRUPT, "opx_point_cloud_read_file", "opx_cloud_lzf_lying.pcd",
                   opx_point_cloud_read_file("opx_cloud_lzf_lying.pcd", &cloud));
    assert_null(cloud);
}

static void a_binary_ply(void **state) {
    static const char header[] = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                                 "property float x\nproperty float y\nproperty float z\nproperty uchar red\n"
                                 "end_header\n";
    unsigned char file[256];
    size_t n = strlen(header), i, count = 0;
    opx_point_cloud *cloud;
    opx_point_cloud_info info;
    float xyz[9];
    (void)state;
    memcpy(file, header, n);
    for (i = 0; i < 3; ++i) {
        const float p[3] = {(float)i, 10.0f + (float)i, -(float)i};
        memcpy(file + n, p, sizeof p);
        file[n + sizeof p] = 200;
        n += sizeof p + 1;
    }
    cloud = read_ok(write_file("opx_cloud.ply", file, n));
    info = info_of(cloud);
    assert_int_equal(info.format, OPX_CLOUD_FORMAT_PLY);
    assert_int_equal(info.encoding, OPX_CLOUD_ENCODING_BINARY);
    assert_int_equal(info.width, 3);
    assert_int_equal(info.height, 1);
    assert_int_equal(info.has_viewpoint, 0);
    assert_ok(opx_point_cloud_get_points(cloud, xyz, 3, 0, &count));
    assert_true(xyz[6] == 2.0f && xyz[7] == 12.0f && xyz[8] == -2.0f);
    opx_point_cloud_destroy(cloud);
}

static void bad_files_name_the_file(void **state) {
    opx_point_cloud *cloud = NOT_NULL_SENTINEL;
    (void)state;
    expect_failure(OPX_ERROR_IO, "opx_point_cloud_read_file", "/nonexistent/frame.pcd",
                   opx_point_cloud_read_file("/nonexistent/frame.pcd", &cloud));
    assert_null(cloud);
    write_text("opx_cloud.xyz", "1 2 3\n");
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_point_cloud_read_file", "opx_cloud.xyz",
                   opx_point_cloud_read_file("opx_cloud.xyz", &cloud));
    write_text("opx_cloud_cut.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 3\nDATA ascii\n1 2 3\n");
    expect_failure(OPX_ERROR_CORRUPT, "opx_point_cloud_read_file", "opx_cloud_cut.pcd",
                   opx_point_cloud_read_file("opx_cloud_cut.pcd", &cloud));
    write_text("opx_cloud_int.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE I I I\nCOUNT 1 1 1\nWIDTH 1\nDATA ascii\n1 2 3\n");
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_point_cloud_read_file", "float32 or float64",
                   opx_point_cloud_read_file("opx_cloud_int.pcd", &cloud));
    write_text("opx_cloud_be.ply", "ply\nformat binary_big_endian 1.0\nelement vertex 0\nend_header\n");
    expect_failure(OPX_ERROR_UNSUPPORTED, "opx_point_cloud_read_file", "binary_big_endian",
                   opx_point_cloud_read_file("opx_cloud_be.ply", &cloud));
    assert_null(cloud);
}

static void bad_arguments_are_named(void **state) {
    opx_point_cloud *cloud = read_ok(write_text("opx_cloud_args.pcd", kAsciiPcd)), *other = NOT_NULL_SENTINEL;
    opx_point_cloud_info info = OPX_POINT_CLOUD_INFO_INIT;
    float xyz[12];
    size_t count;
    (void)state;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_read_file", "path",
                   opx_point_cloud_read_file(NULL, &other));
    assert_null(other);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_read_file", "out",
                   opx_point_cloud_read_file("opx_cloud_args.pcd", NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_get_info", "cloud",
                   opx_point_cloud_get_info(NULL, &info));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_get_info", "out",
                   opx_point_cloud_get_info(cloud, NULL));
    info.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_point_cloud_get_info", "out->struct_size",
                   opx_point_cloud_get_info(cloud, &info));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_get_points", "cloud",
                   opx_point_cloud_get_points(NULL, xyz, 4, 0, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_get_points", "out_count",
                   opx_point_cloud_get_points(cloud, xyz, 4, 0, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_get_points", "out_xyz",
                   opx_point_cloud_get_points(cloud, NULL, 4, 0, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_get_points", "stride 8",
                   opx_point_cloud_get_points(cloud, xyz, 4, 8, &count));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_point_cloud_get_points", "stride 13",
                   opx_point_cloud_get_points(cloud, xyz, 4, 13, &count));
    opx_point_cloud_destroy(cloud);
    opx_point_cloud_destroy(NULL);
}

/* A caller built against an older header: no byte past its struct_size. */
static void get_info_writes_no_further_than_struct_size(void **state) {
    opx_point_cloud *cloud = read_ok(write_text("opx_cloud_old.pcd", kAsciiPcd));
    opx_point_cloud_info info;
    const uint32_t old_size = (uint32_t)offsetof(opx_point_cloud_info, width);
    (void)state;
    memset(&info, 0x5c, sizeof info);
    info.struct_size = old_size;
    assert_ok(opx_point_cloud_get_info(cloud, &info));
    assert_int_equal(info.struct_size, old_size);
    assert_int_equal(info.point_count, 4);
    assert_true(((const unsigned char *)&info)[old_size] == 0x5c);
    assert_true(((const unsigned char *)&info)[sizeof info - 1] == 0x5c);
    opx_point_cloud_destroy(cloud);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(an_organized_ascii_pcd_and_its_viewpoint),
        cmocka_unit_test(points_go_to_a_strided_buffer),
        cmocka_unit_test(a_small_buffer_gets_the_count_and_nothing_else),
        cmocka_unit_test(a_compressed_pcd),
        cmocka_unit_test(a_binary_ply),
        cmocka_unit_test(bad_files_name_the_file),
        cmocka_unit_test(bad_arguments_are_named),
        cmocka_unit_test(get_info_writes_no_further_than_struct_size),
    };
    return cmocka_run_group_tests_name("c_point_cloud", tests, NULL, NULL);
}
