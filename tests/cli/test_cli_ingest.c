/*
 * cli_ingest: `octoprox ingest` and `octoprox info` on clouds written here
 * (PCD ascii/binary, PLY ascii/binary_little_endian): the map equals the
 * library's own insert of the same points, updates accumulate, and bad
 * command lines (exit 2), malformed files and output that cannot be
 * written (exit 3) give messages.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"

#include <octoprox/octoprox.h>

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmocka.h>

#define NX 21
#define NZ 11
#define N_POINTS (NX * NZ)

static float g_points[N_POINTS][3];

/* A wall 2 m ahead of the sensor (sensor frame), 2 m wide, 1 m high. */
static void make_wall(void) {
    int i, j;
    for (i = 0; i < NX; ++i)
        for (j = 0; j < NZ; ++j) {
            g_points[i * NZ + j][0] = 2.0f;
            g_points[i * NZ + j][1] = -1.0f + 0.1f * (float)i;
            g_points[i * NZ + j][2] = 0.1f * (float)j;
        }
}

static const char *write_pcd(const char *name, int binary) {
    static char text[1 << 16];
    size_t n = (size_t)snprintf(text, sizeof text,
                                "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z rgb\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\n"
                                "WIDTH %d\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA %s\n",
                                N_POINTS, N_POINTS, binary ? "binary" : "ascii");
    int i;
    for (i = 0; i < N_POINTS; ++i) {
        if (binary) {
            const uint32_t rgb = 0x00ff00u;
            memcpy(text + n, g_points[i], 12);
            memcpy(text + n + 12, &rgb, 4);
            n += 16;
        } else {
            n += (size_t)snprintf(text + n, sizeof text - n, "%.9g %.9g %.9g 4278190080\n", g_points[i][0],
                                  g_points[i][1], g_points[i][2]);
        }
    }
    return write_bytes(name, text, n);
}

static const char *write_ply(const char *name, int binary) {
    static char text[1 << 16];
    size_t n = (size_t)snprintf(text, sizeof text,
                                "ply\nformat %s 1.0\ncomment written by cli_ingest\nelement vertex %d\n"
                                "property double x\nproperty double y\nproperty double z\nproperty uchar red\n"
                                "element face 0\nproperty list uchar int vertex_indices\nend_header\n",
                                binary ? "binary_little_endian" : "ascii", N_POINTS);
    int i, axis;
    for (i = 0; i < N_POINTS; ++i) {
        if (binary) {
            for (axis = 0; axis < 3; ++axis) {
                const double v = g_points[i][axis];
                memcpy(text + n, &v, 8);
                n += 8;
            }
            text[n++] = 7;
        } else {
            n += (size_t)snprintf(text + n, sizeof text - n, "%.9g %.9g %.9g 7\n", g_points[i][0], g_points[i][1],
                                  g_points[i][2]);
        }
    }
    return write_bytes(name, text, n);
}

/* The map the library makes of the wall seen from (0, 0, 1), `times` times. */
static opx_octree_stats library_map(int times, int32_t mode) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    opx_octree *tree = NULL;
    int i;
    options.resolution = 0.1;
    insert.mode = mode;
    insert.sensor_pose.position[2] = 1.0;
    assert_int_equal(opx_octree_create(&options, &tree), OPX_OK);
    for (i = 0; i < times; ++i)
        assert_int_equal(opx_octree_insert_points(tree, g_points, N_POINTS, 0, OPX_SCALAR_FLOAT32, &insert, NULL), OPX_OK);
    assert_int_equal(opx_octree_get_stats(tree, &stats), OPX_OK);
    opx_octree_destroy(tree);
    return stats;
}

static void assert_info_matches(const char *map, const opx_octree_stats *expected) {
    static cli_result r;
    run_cli(&r, "info '%s' --json", map);
    assert_int_equal(r.code, 0);
    assert_true(json_field(r.out, "resolution") == 0.1);
    assert_int_equal((long long)json_field(r.out, "occupied"), (long long)expected->leaves_occupied);
    assert_int_equal((long long)json_field(r.out, "free"), (long long)expected->leaves_free);
    assert_int_equal((long long)json_field(r.out, "uncertain"), 0);
    assert_int_equal((long long)json_field(r.out, "memory_bytes"), (long long)expected->memory_bytes);
}

static void every_format_gives_the_library_map(void **state) {
    static const char *const names[4] = {"ascii.pcd", "binary.pcd", "ascii.ply", "binary.ply"};
    static cli_result r;
    const opx_octree_stats expected = library_map(1, OPX_INSERT_RAYCAST);
    int i;
    (void)state;
    assert_true(expected.leaves_occupied > 10 && expected.leaves_free > 10);
    for (i = 0; i < 4; ++i) {
        const char *cloud = i < 2 ? write_pcd(names[i], i == 1) : write_ply(names[i], i == 3);
        char map[64];
        snprintf(map, sizeof map, "map%d.bt", i);
        run_cli(&r, "ingest '%s' --sensor-pose 0,0,1 --res 0.1 -o '%s' --json", cloud, scratch_path(map));
        assert_int_equal(r.code, 0);
        assert_string_equal(r.err, ""); /* stderr is a file here, not a terminal: no progress bar */
        assert_int_equal(json_bool(r.out, "updated"), 0);
        assert_int_equal((long long)json_field(r.out, "points_used"), N_POINTS);
        assert_int_equal((long long)json_field(r.out, "occupied"), (long long)expected.leaves_occupied);
        assert_info_matches(scratch_path(map), &expected);
    }
}

static void an_existing_map_is_updated(void **state) {
    static cli_result r;
    const char *cloud = write_pcd("update.pcd", 1), *map = scratch_path("update.ot");
    const opx_octree_stats twice = library_map(2, OPX_INSERT_RAYCAST);
    (void)state;
    run_cli(&r, "ingest '%s' --sensor-pose 0,0,1,0,0,0,1 --res 0.1 -o '%s'", cloud, map);
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "wrote"));
    run_cli(&r, "ingest '%s' --sensor-pose=0,0,1 -o '%s' --json", cloud, map);
    assert_int_equal(r.code, 0);
    assert_int_equal(json_bool(r.out, "updated"), 1);
    assert_info_matches(map, &twice);
    /* A resolution that is not the map's is a usage error. */
    run_cli(&r, "ingest '%s' --res 0.2 -o '%s'", cloud, map);
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "resolution"));
}

static void endpoints_mode_has_no_free_space(void **state) {
    static cli_result r;
    const char *cloud = write_pcd("endpoints.pcd", 0), *map = scratch_path("endpoints.bt");
    const opx_octree_stats expected = library_map(1, OPX_INSERT_ENDPOINTS);
    (void)state;
    run_cli(&r, "ingest '%s' --endpoints --sensor-pose 0,0,1 --res 0.1 -o '%s'", cloud, map);
    assert_int_equal(r.code, 0);
    assert_int_equal(expected.leaves_free, 0);
    assert_info_matches(map, &expected);
}

static void expect_usage_error(const char *arguments, const char *message) {
    static cli_result r;
    run_cli(&r, "%s", arguments);
    if (r.code != 2) fail_msg("'octoprox %s' exited %d, not 2; stderr: %s", arguments, r.code, r.err);
    if (strstr(r.err, message) == NULL) fail_msg("'octoprox %s': stderr \"%s\" lacks \"%s\"", arguments, r.err, message);
}

static void bad_command_lines_exit_2(void **state) {
    const char *cloud = write_pcd("usage.pcd", 0);
    char line[1024];
    (void)state;
    expect_usage_error("", "usage: octoprox");
    expect_usage_error("frobnicate", "unknown command 'frobnicate'");
    expect_usage_error("info", "no map file given");
    expect_usage_error("info a.bt b.bt", "one map only");
    expect_usage_error("info --frob a.bt", "unknown option '--frob'");
    expect_usage_error("ingest -o x.bt", "no cloud given");
    snprintf(line, sizeof line, "ingest '%s'", cloud);
    expect_usage_error(line, "no output map");
    snprintf(line, sizeof line, "ingest '%s' -o x.txt", cloud);
    expect_usage_error(line, "must end in .bt, .ot or .opx");
    snprintf(line, sizeof line, "ingest '%s' -o x.bt --sensor-pose 1,2", cloud);
    expect_usage_error(line, "--sensor-pose needs");
    snprintf(line, sizeof line, "ingest '%s' -o x.bt --sensor-pose 1,2,3,0,0,0,0", cloud);
    expect_usage_error(line, "--sensor-pose needs");
    snprintf(line, sizeof line, "ingest '%s' -o x.bt --res -1", cloud);
    expect_usage_error(line, "--res needs");
    snprintf(line, sizeof line, "ingest '%s' -o x.bt --res nan", cloud);
    expect_usage_error(line, "--res needs");
    snprintf(line, sizeof line, "ingest '%s' -o x.bt --res 5e-324", cloud);
    expect_usage_error(line, "resolution");
    snprintf(line, sizeof line, "ingest '%s' -o x.bt --res 2e6", cloud);
    expect_usage_error(line, "resolution");
    expect_usage_error("ingest cloud.xyz -o x.bt", "not a .pcd or .ply cloud, nor a .png, .tif or .tiff");
    snprintf(line, sizeof line, "ingest '%s' -o", cloud);
    expect_usage_error(line, "-o needs");
}

static void expect_input_error(const char *name, const char *contents, size_t size, const char *message) {
    static cli_result r;
    const char *cloud = write_bytes(name, contents, size);
    run_cli(&r, "ingest '%s' -o '%s'", cloud, scratch_path("never.bt"));
    if (r.code != 3) fail_msg("%s: exit %d, not 3; stderr: %s", name, r.code, r.err);
    if (strstr(r.err, message) == NULL || strstr(r.err, name) == NULL)
        fail_msg("%s: stderr \"%s\" lacks \"%s\" or the file name", name, r.err, message);
}

static void malformed_files_exit_3(void **state) {
    static const char kTruncated[] = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                     "WIDTH 10\nHEIGHT 1\nPOINTS 10\nDATA binary\n0123456789";
    static const char kNotNumber[] = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                     "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1 two 3\n";
    static const char kNoZ[] = "VERSION 0.7\nFIELDS x y\nSIZE 4 4\nTYPE F F\nCOUNT 1 1\nWIDTH 1\nHEIGHT 1\nDATA ascii\n1 2\n";
    static const char kPlyNotPly[] = "plx\nformat ascii 1.0\nend_header\n";
    static const char kPlyBigEndian[] = "ply\nformat binary_big_endian 1.0\nelement vertex 1\nproperty float x\nend_header\n";
    static const char kPlyNoVertex[] = "ply\nformat ascii 1.0\nelement face 0\nproperty list uchar int v\nend_header\n";
    static const char kPlyIntX[] = "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty int y\n"
                                   "property int z\nend_header\n1 2 3\n";
    static const char kPlyShort[] = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                    "property float z\nend_header\n1 2 3\n4 5\n";
    static const char kPlyText[] = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                                   "property float z\nend_header\n1 2 abc\n";
    static cli_result r;
    (void)state;
    expect_input_error("truncated.pcd", kTruncated, sizeof kTruncated - 1, "truncated");
    expect_input_error("notnumber.pcd", kNotNumber, sizeof kNotNumber - 1, "not a number");
    expect_input_error("noz.pcd", kNoZ, sizeof kNoZ - 1, "no field \"z\"");
    expect_input_error("empty.pcd", "", 0, "DATA");
    expect_input_error("notply.ply", kPlyNotPly, sizeof kPlyNotPly - 1, "not a PLY file");
    expect_input_error("bigendian.ply", kPlyBigEndian, sizeof kPlyBigEndian - 1, "binary_big_endian");
    expect_input_error("novertex.ply", kPlyNoVertex, sizeof kPlyNoVertex - 1, "no vertex element");
    expect_input_error("intx.ply", kPlyIntX, sizeof kPlyIntX - 1, "not float or double");
    expect_input_error("short.ply", kPlyShort, sizeof kPlyShort - 1, "truncated");
    expect_input_error("text.ply", kPlyText, sizeof kPlyText - 1, "not a number");
    run_cli(&r, "ingest '%s' -o x.bt", scratch_path("missing.pcd"));
    assert_int_equal(r.code, 3);
    assert_non_null(strstr(r.err, "cannot open"));
    run_cli(&r, "info '%s'", write_text("garbage.bt", "# not a map\n"));
    assert_int_equal(r.code, 3);
    assert_non_null(strstr(r.err, "garbage.bt"));
    run_cli(&r, "info '%s'", scratch_path("missing.bt"));
    assert_int_equal(r.code, 3);
}

static long file_size(const char *path) {
    struct stat info;
    return stat(path, &info) == 0 ? (long)info.st_size : -1;
}

/* /dev/full takes no byte: every report written there must fail loudly. */
static void a_report_to_a_full_device_exits_3(void **state) {
    static cli_result r;
    const char *cloud = write_pcd("full.pcd", 1);
    char map[512];
    (void)state;
    if (access("/dev/full", W_OK) != 0) skip();
    snprintf(map, sizeof map, "%s", scratch_path("full.bt"));
    run_cli(&r, "ingest '%s' --sensor-pose 0,0,1 --res 0.1 -o '%s'", cloud, map);
    assert_int_equal(r.code, 0);
    run_cli_to(&r, "/dev/full", "info '%s'", map);
    if (r.code != 3) fail_msg("info > /dev/full exited %d, not 3; stderr: %s", r.code, r.err);
    assert_non_null(strstr(r.err, "cannot write the standard output"));
    run_cli_to(&r, "/dev/full", "info '%s' --json", map);
    assert_int_equal(r.code, 3);
    run_cli_to(&r, "/dev/full", "ingest '%s' -o '%s' --json", cloud, map);
    assert_int_equal(r.code, 3);
    run_cli_to(&r, "/dev/full", "--help");
    assert_int_equal(r.code, 3);
    run_cli_to(&r, "/dev/null", "info '%s'", map);
    assert_int_equal(r.code, 0);
}

/* A map larger than the file size limit (ulimit -f 1: 512 bytes): the
 * save fails with an I/O error (no signal kills the tool) and leaves
 * neither the map nor its temporary file (".limit.bt.*") behind. */
static void a_map_past_the_file_size_limit_exits_3(void **state) {
    static cli_result r;
    const char *cloud = write_pcd("limit.pcd", 1);
    char map[512], unlimited[512];
    (void)state;
    snprintf(map, sizeof map, "%s", scratch_path("limit.bt"));
    snprintf(unlimited, sizeof unlimited, "%s", scratch_path("unlimited.bt"));
    run_cli(&r, "ingest '%s' --sensor-pose 0,0,1 --res 0.1 -o '%s'", cloud, unlimited);
    assert_int_equal(r.code, 0);
    if (file_size(unlimited) <= 512) fail_msg("the map is only %ld bytes: it fits the limit", file_size(unlimited));
    run_cli_file_limit(&r, 1, "ingest '%s' --sensor-pose 0,0,1 --res 0.1 -o '%s'", cloud, map);
    if (r.code != 3) fail_msg("ingest under ulimit -f 1 exited %d, not 3; stderr: %s", r.code, r.err);
    assert_non_null(strstr(r.err, "limit.bt"));
    assert_int_equal(scratch_files_starting(".limit.bt."), 0);
    assert_int_equal(file_size(map), -1);
}

static void every_command_has_help(void **state) {
    static const char *const commands[5] = {"", "info ", "ingest ", "check ", "export "};
    static cli_result r;
    int i;
    (void)state;
    for (i = 0; i < 5; ++i) {
        char usage[64];
        run_cli(&r, "%s--help", commands[i]);
        assert_int_equal(r.code, 0);
        snprintf(usage, sizeof usage, "usage: octoprox %s", commands[i]);
        if (strstr(r.out, usage) == NULL) fail_msg("'%s--help' lacks \"%s\": %s", commands[i], usage, r.out);
        assert_non_null(strstr(r.out, "exit codes"));
        assert_string_equal(r.err, "");
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_format_gives_the_library_map),
        cmocka_unit_test(an_existing_map_is_updated),
        cmocka_unit_test(endpoints_mode_has_no_free_space),
        cmocka_unit_test(bad_command_lines_exit_2),
        cmocka_unit_test(malformed_files_exit_3),
        cmocka_unit_test(a_report_to_a_full_device_exits_3),
        cmocka_unit_test(a_map_past_the_file_size_limit_exits_3),
        cmocka_unit_test(every_command_has_help),
    };
    make_wall();
    return cmocka_run_group_tests_name("cli_ingest", tests, NULL, NULL);
}
