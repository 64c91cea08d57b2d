/*
 * cli_ingest_robot: `octoprox ingest --urdf` filters a robot out of the
 * inputs (self-filtering).  A ball on a prismatic joint, placed by
 * --joints and --base-pose, stands in front of the sensor: the report
 * counts the point on it and the one behind it, the map equals the
 * library's own filtered insert, padding widens the band, a ghost inside
 * the robot is cleared with --clear-robot-volume, depth images are
 * filtered too, and the robot options without --urdf or with bad values
 * exit 2.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "depth_files.h"

#include <octoprox/octoprox.h>

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

/* The ball (radius 0.2) stands at (1 + slide, 0, 0) from the base. */
static const char kSlider[] =
    "<robot name=\"slider\">\n"
    "  <link name=\"base\"/>\n"
    "  <link name=\"ball\"><collision><geometry><sphere radius=\"0.2\"/></geometry></collision></link>\n"
    "  <joint name=\"slide\" type=\"prismatic\"><parent link=\"base\"/><child link=\"ball\"/>\n"
    "    <origin xyz=\"1 0 0\"/><axis xyz=\"1 0 0\"/><limit lower=\"-2\" upper=\"2\" velocity=\"1\" effort=\"1\"/>\n"
    "  </joint>\n"
    "</robot>\n";

/* With the ball at (2, 0, 0) and the sensor at the origin: on the ball's
 * near side, behind it, elsewhere. */
static const float kFrame[3][3] = {{1.81f, 0.0f, 0.0f}, {3.0f, 0.0f, 0.0f}, {1.0f, 1.0f, 0.0f}};

static const char *write_cloud(const char *name, const float (*points)[3], int count) {
    static char text[4096];
    int n = snprintf(text, sizeof text,
                     "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                     "WIDTH %d\nHEIGHT 1\nPOINTS %d\nDATA ascii\n", count, count);
    int i;
    for (i = 0; i < count; ++i)
        n += snprintf(text + n, sizeof text - (size_t)n, "%.9g %.9g %.9g\n", points[i][0], points[i][1], points[i][2]);
    return write_text(name, text);
}

/* The robot's URDF, written once; the path outlives scratch_path's slots. */
static const char *urdf_path(void) {
    static char path[512] = "";
    if (path[0] == '\0') snprintf(path, sizeof path, "%s", write_text("slider.urdf", kSlider));
    return path;
}

/* A copy of a scratch path that outlives scratch_path's slots. */
static void kept(char *buffer, size_t size, const char *path) { snprintf(buffer, size, "%s", path); }

static long long field(const cli_result *r, const char *key) { return (long long)json_field(r->out, key); }

/* The map the library makes of kFrame with the ball at (2, 0, 0). */
static opx_octree_stats library_map(void) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    opx_octree *tree = NULL;
    opx_linkset *robot = NULL;
    const double slide = 1.0;
    assert_int_equal(opx_linkset_load_urdf_string(kSlider, NULL, &robot), OPX_OK);
    assert_int_equal(opx_linkset_set_joint_positions(robot, &slide, 1, NULL), OPX_OK);
    assert_int_equal(opx_octree_create(&options, &tree), OPX_OK);
    insert.robot = robot;
    assert_int_equal(opx_octree_insert_points(tree, kFrame, 3, 0, OPX_SCALAR_FLOAT32, &insert, NULL), OPX_OK);
    assert_int_equal(opx_octree_get_stats(tree, &stats), OPX_OK);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
    return stats;
}

static void filters_the_robot_out_of_a_cloud(void **state) {
    static cli_result r;
    const char *urdf = urdf_path();
    const char *cloud = write_cloud("frame.pcd", kFrame, 3);
    const opx_octree_stats expected = library_map();
    (void)state;
    run_cli(&r, "ingest '%s' -o '%s' --urdf '%s' --joints slide=1 --json", cloud, scratch_path("frame.bt"), urdf);
    assert_int_equal(r.code, 0);
    assert_int_equal(field(&r, "points_used"), 1);
    assert_int_equal(field(&r, "points_on_robot"), 1);
    assert_int_equal(field(&r, "points_shadowed"), 1);
    assert_int_equal(field(&r, "cells_cleared"), 0);
    assert_int_equal(field(&r, "occupied"), (long long)expected.leaves_occupied);
    assert_int_equal(field(&r, "free"), (long long)expected.leaves_free);
    /* The same robot placed by --base-pose; the text report. */
    run_cli(&r, "ingest '%s' -o '%s' --urdf '%s' --joints slide=0.5 --base-pose 0.5,0,0", cloud,
            scratch_path("based.bt"), urdf);
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "1 used, 0 skipped, 1 on the robot, 1 shadowed"));
    assert_non_null(strstr(r.out, "missed, 0 cleared"));
}

static void without_a_robot_nothing_is_filtered(void **state) {
    static cli_result r;
    const char *cloud = write_cloud("plain.pcd", kFrame, 3);
    (void)state;
    run_cli(&r, "ingest '%s' -o '%s' --json", cloud, scratch_path("plain.bt"));
    assert_int_equal(r.code, 0);
    assert_int_equal(field(&r, "points_used"), 3);
    assert_int_equal(field(&r, "points_on_robot") + field(&r, "points_shadowed") + field(&r, "cells_cleared"), 0);
    run_cli(&r, "ingest '%s' -o '%s'", cloud, scratch_path("plain.bt"));
    assert_null(strstr(r.out, "on the robot"));
}

/* A point 0.1 m in front of the ball: on the robot once the paddings
 * (--padding, the link's, and --robot-padding, the filter's) reach it. */
static void paddings_widen_the_band(void **state) {
    static const float near[1][3] = {{1.7f, 0.0f, 0.0f}};
    static const char *const paddings[3] = {"", "--robot-padding 0.15", "--padding 0.06 --robot-padding=0.06"};
    static cli_result r;
    const char *urdf = urdf_path();
    char cloud[512], map[512];
    int i;
    (void)state;
    kept(cloud, sizeof cloud, write_cloud("near.pcd", near, 1));
    kept(map, sizeof map, scratch_path("near.bt"));
    for (i = 0; i < 3; ++i) {
        run_cli(&r, "ingest '%s' -o '%s' --urdf '%s' --joints slide=1 %s --json", cloud, map, urdf, paddings[i]);
        assert_int_equal(r.code, 0);
        assert_int_equal(field(&r, "points_on_robot"), i > 0);
    }
}

/* An obstacle where the ball then stands stays without
 * --clear-robot-volume and becomes free with it. */
static void clear_robot_volume_clears_a_ghost(void **state) {
    static const float ghost[1][3] = {{2.0f, 0.0f, 0.0f}}, far[1][3] = {{0.0f, 3.0f, 0.0f}};
    static cli_result r;
    const char *urdf = urdf_path();
    char ghost_cloud[512], far_cloud[512], map[512];
    int clear;
    (void)state;
    kept(ghost_cloud, sizeof ghost_cloud, write_cloud("ghost.pcd", ghost, 1));
    kept(far_cloud, sizeof far_cloud, write_cloud("far.pcd", far, 1));
    for (clear = 0; clear < 2; ++clear) {
        opx_octree *tree = NULL;
        const double at[3] = {2.0, 0.0, 0.0};
        opx_cell_info cell = OPX_CELL_INFO_INIT;
        kept(map, sizeof map, scratch_path(clear ? "cleared.ot" : "kept.ot"));
        run_cli(&r, "ingest '%s' -o '%s'", ghost_cloud, map);
        assert_int_equal(r.code, 0);
        run_cli(&r, "ingest '%s' -o '%s' --urdf '%s' --joints slide=1 %s --json", far_cloud, map, urdf,
                clear ? "--clear-robot-volume" : "");
        assert_int_equal(r.code, 0);
        assert_int_equal(field(&r, "cells_cleared") > 0, clear);
        assert_int_equal(opx_octree_load_file(map, NULL, &tree), OPX_OK);
        assert_int_equal(opx_octree_classify(tree, at, &cell), OPX_OK);
        assert_int_equal(cell.cell_class, clear ? OPX_CELL_FREE : OPX_CELL_OCCUPIED);
        opx_octree_destroy(tree);
    }
}

/* A 9 x 9 depth image, the ball 2 m along the optical axis (z): the
 * centre pixel on it, the pixels behind it shadowed. */
static void filters_depth_images(void **state) {
    static uint16_t depth[9 * 9];
    static cli_result r;
    const char *urdf = urdf_path();
    const char *image;
    int i;
    (void)state;
    for (i = 0; i < 81; ++i) depth[i] = 3000; /* 3 m */
    depth[4 * 9 + 4] = 1850;                  /* 1.85 m: on the ball's near side */
    image = write_png("robot.png", depth, 9, 9, 16, 1);
    run_cli(&r, "ingest '%s' -o '%s' --intrinsics 10,10,4,4 --depth-scale 1000 --urdf '%s' --joints slide=0 "
            "--base-pose -1,0,2 --json", image, scratch_path("depth.bt"), urdf);
    assert_int_equal(r.code, 0);
    assert_int_equal(field(&r, "points_on_robot"), 1);
    assert_true(field(&r, "points_shadowed") > 0);
    assert_int_equal(field(&r, "points_used") + field(&r, "points_on_robot") + field(&r, "points_shadowed"), 81);
}

static void expect_usage_error(const char *options, const char *message) {
    static cli_result r;
    const char *cloud = write_cloud("usage.pcd", kFrame, 3);
    run_cli(&r, "ingest '%s' -o '%s' %s", cloud, scratch_path("usage.bt"), options);
    if (r.code != 2) fail_msg("'ingest ... %s' exited %d, not 2; stderr: %s", options, r.code, r.err);
    if (strstr(r.err, message) == NULL) fail_msg("'ingest ... %s': stderr \"%s\" lacks \"%s\"", options, r.err, message);
}

static void bad_robot_options_exit_2(void **state) {
    /* Options after --urdf ROBOT, and the message they give. */
    static const char *const with_urdf[][2] = {
        {"--robot-padding -0.1", "--robot-padding needs a distance"},
        {"--robot-padding nan", "--robot-padding needs a distance"},
        {"--robot-padding", "--robot-padding needs a distance"},
        {"--joints nope=1", "nope"},
    };
    char line[1024];
    size_t i;
    (void)state;
    expect_usage_error("--robot-padding 0.1", "--robot-padding needs --urdf");
    expect_usage_error("--clear-robot-volume", "--clear-robot-volume needs --urdf");
    expect_usage_error("--joints=slide=1", "--joints needs --urdf");
    for (i = 0; i < sizeof with_urdf / sizeof with_urdf[0]; ++i) {
        snprintf(line, sizeof line, "--urdf '%s' %s", urdf_path(), with_urdf[i][0]);
        expect_usage_error(line, with_urdf[i][1]);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(filters_the_robot_out_of_a_cloud),
        cmocka_unit_test(without_a_robot_nothing_is_filtered),
        cmocka_unit_test(paddings_widen_the_band),
        cmocka_unit_test(clear_robot_volume_clears_a_ghost),
        cmocka_unit_test(filters_depth_images),
        cmocka_unit_test(bad_robot_options_exit_2),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
