/*
 * cli_ingest_frames: where `octoprox ingest` puts a cloud's sensor.  A
 * PCD's VIEWPOINT is the sensor pose when --sensor-pose is not given (the
 * map equals the one made with that pose given), --sensor-pose wins over
 * it, --optical-frame turns a camera's optical frame (z forward, x right,
 * y down) into the z-up body frame the pose places, a VIEWPOINT that is
 * no pose is an input error, and LZF-compressed PCDs are read.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"

#include <lzf.h>
#include <octoprox/octoprox.h>

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#define XYZ "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
#define N_POINTS 60

static float g_points[N_POINTS][3];

/* A patch of a wall 2.05 m ahead along z (a camera's optical frame),
 * x -0.25 .. 0.25, y -0.45 .. 0.45: no point on a 10 cm cell's face. */
static void make_patch(void) {
    int i;
    for (i = 0; i < N_POINTS; ++i) {
        g_points[i][0] = -0.25f + 0.1f * (float)(i % 6);
        g_points[i][1] = -0.45f + 0.1f * (float)(i / 6);
        g_points[i][2] = 2.05f;
    }
}

/* An ascii PCD of the patch with `viewpoint_line` ("" for none). */
static const char *write_patch(const char *name, const char *viewpoint_line) {
    static char text[1 << 14];
    size_t n = (size_t)snprintf(text, sizeof text, XYZ "WIDTH %d\n%sDATA ascii\n", N_POINTS, viewpoint_line);
    int i;
    for (i = 0; i < N_POINTS; ++i)
        n += (size_t)snprintf(text + n, sizeof text - n, "%.9g %.9g %.9g\n", g_points[i][0], g_points[i][1],
                              g_points[i][2]);
    return write_bytes(name, text, n);
}

static void assert_near(double value, double expected, double tolerance) {
    if (fabs(value - expected) > tolerance) fail_msg("%.9f is not %.9f", value, expected);
}

static opx_octree_stats stats_of(const char *map) {
    opx_octree *tree = NULL;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    assert_int_equal(opx_octree_load_file(map, NULL, &tree), OPX_OK);
    assert_int_equal(opx_octree_get_stats(tree, &stats), OPX_OK);
    opx_octree_destroy(tree);
    return stats;
}

static void assert_same_map(const char *a, const char *b) {
    const opx_octree_stats x = stats_of(a), y = stats_of(b);
    assert_int_equal(x.leaves_occupied, y.leaves_occupied);
    assert_int_equal(x.leaves_free, y.leaves_free);
    assert_memory_equal(x.occupied_min, y.occupied_min, sizeof x.occupied_min);
    assert_memory_equal(x.known_max, y.known_max, sizeof x.known_max);
}

/* The seven numbers of "sensor_pose": [...] in the JSON report. */
static void sensor_pose_of(const char *json, double pose[7]) {
    const char *at = strstr(json, "\"sensor_pose\": [");
    assert_non_null(at);
    assert_int_equal(sscanf(at + strlen("\"sensor_pose\": ["), "%lf, %lf, %lf, %lf, %lf, %lf, %lf", &pose[0],
                            &pose[1], &pose[2], &pose[3], &pose[4], &pose[5], &pose[6]),
                     7);
}

static void the_viewpoint_is_the_sensor_pose_unless_one_is_given(void **state) {
    static cli_result r;
    char with[512], without[512], a[512], b[512];
    double pose[7];
    (void)state;
    /* scratch_path's buffers are reused: the paths are copied. */
    snprintf(with, sizeof with, "%s", write_patch("viewpoint.pcd", "VIEWPOINT 1 2 0.5 0.9238795 0 0 0.3826834\n"));
    snprintf(without, sizeof without, "%s", write_patch("plain.pcd", ""));
    snprintf(a, sizeof a, "%s", scratch_path("viewpoint.bt"));
    snprintf(b, sizeof b, "%s", scratch_path("given.bt"));
    run_cli(&r, "ingest '%s' --res 0.1 -o '%s' --json", with, a);
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "\"sensor_pose_from\": \"VIEWPOINT\""));
    sensor_pose_of(r.out, pose);
    assert_true(pose[0] == 1.0 && pose[1] == 2.0 && pose[2] == 0.5);
    assert_true(pose[5] == 0.3826834 && pose[6] == 0.9238795); /* qz, qw */
    run_cli(&r, "ingest '%s' --res 0.1 --sensor-pose 1,2,0.5,0,0,0.3826834,0.9238795 -o '%s'", without, b);
    assert_int_equal(r.code, 0);
    assert_same_map(a, b);
    /* The text report says where the pose came from. */
    run_cli(&r, "ingest '%s' --res 0.1 -o '%s'", with, scratch_path("text.bt"));
    assert_non_null(strstr(r.out, "sensor pose from the file's VIEWPOINT: 1,2,0.5,0,0,0.382683,0.9238"));
    /* --sensor-pose wins over the VIEWPOINT. */
    run_cli(&r, "ingest '%s' --res 0.1 --sensor-pose 0,0,1 -o '%s' --json", with, scratch_path("option.bt"));
    assert_non_null(strstr(r.out, "\"sensor_pose_from\": \"--sensor-pose\""));
    run_cli(&r, "ingest '%s' --res 0.1 -o '%s' --json", without, scratch_path("default.bt"));
    assert_non_null(strstr(r.out, "\"sensor_pose_from\": \"default\""));
}

static void the_optical_frame_is_turned_into_the_body_frame(void **state) {
    static cli_result r;
    const char *patch = write_patch("optical.pcd", "");
    char map[512];
    double pose[7];
    opx_octree_stats stats;
    (void)state;
    snprintf(map, sizeof map, "%s", scratch_path("optical.bt"));
    run_cli(&r, "ingest '%s' --res 0.1 --optical-frame --sensor-pose 0,0,1 -o '%s' --json", patch, map);
    assert_int_equal(r.code, 0);
    sensor_pose_of(r.out, pose);
    assert_true(pose[2] == 1.0 && pose[3] == -0.5 && pose[4] == 0.5 && pose[5] == -0.5 && pose[6] == 0.5);
    /* Cells 2.05 m ahead along the map's x; optical x right is -y, optical
     * y down (-0.45 .. 0.45) is -z from the camera at z = 1. */
    stats = stats_of(map);
    assert_near(stats.occupied_min[0], 2.0, 1e-9);
    assert_near(stats.occupied_max[0], 2.1, 1e-9);
    assert_near(stats.occupied_min[1], -0.3, 1e-9);
    assert_near(stats.occupied_max[1], 0.3, 1e-9);
    assert_near(stats.occupied_min[2], 0.5, 1e-9);
    assert_near(stats.occupied_max[2], 1.5, 1e-9);
}

static void a_viewpoint_that_is_no_pose_is_an_input_error(void **state) {
    static cli_result r;
    (void)state;
    run_cli(&r, "ingest '%s' -o '%s'", write_patch("zero.pcd", "VIEWPOINT 0 0 0 0 0 0 0\n"), scratch_path("zero.bt"));
    assert_int_equal(r.code, 3);
    assert_non_null(strstr(r.err, "zero.pcd: its VIEWPOINT is no pose"));
    assert_non_null(strstr(r.err, "--sensor-pose"));
    run_cli(&r, "ingest '%s' --sensor-pose 0,0,1 -o '%s'", scratch_path("zero.pcd"), scratch_path("zero.bt"));
    assert_int_equal(r.code, 0);
}

static void a_compressed_pcd_is_ingested_like_its_ascii_twin(void **state) {
    static unsigned char file[1 << 14];
    static float fields[3 * N_POINTS];
    static cli_result r;
    const char *header = XYZ "WIDTH 60\nDATA binary_compressed\n";
    const size_t n = strlen(header);
    unsigned int packed;
    uint32_t sizes[2];
    int i, axis;
    (void)state;
    for (axis = 0; axis < 3; ++axis)
        for (i = 0; i < N_POINTS; ++i) fields[axis * N_POINTS + i] = g_points[i][axis];
    packed = lzf_compress(fields, sizeof fields, file + n + 8, sizeof file - n - 8);
    assert_true(packed > 0);
    sizes[0] = packed, sizes[1] = sizeof fields;
    memcpy(file, header, n);
    memcpy(file + n, sizes, sizeof sizes); /* little-endian, as on every machine this runs on */
    write_bytes("lzf.pcd", file, n + 8 + packed);
    run_cli(&r, "ingest '%s' --res 0.1 -o '%s' --json", scratch_path("lzf.pcd"), scratch_path("lzf.bt"));
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "\"format\": \"pcd binary_compressed\""));
    run_cli(&r, "ingest '%s' --res 0.1 -o '%s'", write_patch("twin.pcd", ""), scratch_path("twin.bt"));
    assert_same_map(scratch_path("lzf.bt"), scratch_path("twin.bt"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_viewpoint_is_the_sensor_pose_unless_one_is_given),
        cmocka_unit_test(the_optical_frame_is_turned_into_the_body_frame),
        cmocka_unit_test(a_viewpoint_that_is_no_pose_is_an_input_error),
        cmocka_unit_test(a_compressed_pcd_is_ingested_like_its_ascii_twin),
    };
    make_patch();
    return cmocka_run_group_tests_name("cli_ingest_frames", tests, NULL, NULL);
}
