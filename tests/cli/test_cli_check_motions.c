/*
 * cli_check_motions: `octoprox check --path` checks the straight joint
 * motion between each two waypoints too.  The slider's tool passes through
 * the wall between two free waypoints (slide 0, then 3): the tool exits 1
 * and reports where the motion first collides, as opx_query_check_motion
 * does at the same resolution, whatever --threads; a path that stops short
 * of the wall is free; bad --resolution and --threads are usage errors.
 * With --certified the same, the fraction being the certified check's.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "cli_scene.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

/* The library's own answer for the motion slide a -> b. */
static opx_motion_result library_motion(double a, double b, double resolution, int32_t check) {
    opx_octree *map = scene_load_map();
    opx_linkset *robot = scene_load_robot(0.0);
    opx_query *query = NULL;
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    uint32_t joints = 0;
    double start[1] = {a}, goal[1] = {b};
    assert_int_equal(opx_linkset_get_joint_count(robot, &joints), OPX_OK);
    assert_int_equal(joints, 1);
    request.resolution = resolution;
    request.check = check;
    assert_int_equal(opx_query_create(NULL, &query), OPX_OK);
    assert_int_equal(opx_query_check_motion(query, map, robot, start, goal, 1, NULL, &request, &result), OPX_OK);
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(map);
    return result;
}

static void a_motion_through_the_wall_collides(void **state) {
    static cli_result r;
    char csv[512];
    const opx_motion_result expected = library_motion(0.0, 3.0, 0.02, OPX_MOTION_SAMPLED);
    (void)state;
    snprintf(csv, sizeof csv, "%s", write_text("through.csv", "slide\n0\n3\n")); /* write_text's buffer is reused */
    assert_int_equal(expected.collided, 1);
    for (int threads = 0; threads <= 2; ++threads) {
        run_cli(&r, "check '%s' --urdf '%s' --path '%s' --resolution 0.02 --threads %d --json", scene_map(),
                scene_urdf(), csv, threads);
        assert_int_equal(r.code, 1);
        assert_int_equal((long long)json_field(r.out, "first_colliding_waypoint"), -1);
        assert_int_equal((long long)json_field_in(r.out, "motions", "count"), 1);
        assert_int_equal((long long)json_field_in(r.out, "motions", "first_colliding"), 0);
        assert_true(json_field_in(r.out, "motions", "first_collision_fraction") == expected.first_collision_fraction);
        assert_true(json_field_in(r.out, "motions", "resolution") == 0.02);
    }
    run_cli(&r, "check '%s' --urdf '%s' --path '%s'", scene_map(), scene_urdf(), csv);
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "first collision between waypoints 0 and 1"));
}

static void certified_motions(void **state) {
    static cli_result r;
    char csv[512];
    const opx_motion_result expected = library_motion(0.0, 3.0, 0.02, OPX_MOTION_CERTIFIED);
    (void)state;
    snprintf(csv, sizeof csv, "%s", write_text("through_certified.csv", "slide\n0\n3\n"));
    assert_int_equal(expected.collided, 1);
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --certified --threads 2 --json", scene_map(), scene_urdf(), csv);
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "\"certified\": true"));
    assert_int_equal((long long)json_field_in(r.out, "motions", "first_colliding"), 0);
    assert_true(json_field_in(r.out, "motions", "first_collision_fraction") == expected.first_collision_fraction);
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --certified", scene_map(), scene_urdf(),
            write_text("short_certified.csv", "slide\n0\n1.8\n0.4\n"));
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "certified"));
    run_cli(&r, "check '%s' --urdf '%s' --certified", scene_map(), scene_urdf());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--certified"));
}

static void a_path_short_of_the_wall_is_free(void **state) {
    static cli_result r;
    (void)state;
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --json", scene_map(), scene_urdf(),
            write_text("short.csv", "slide\n0\n1.8\n0.4\n"));
    assert_int_equal(r.code, 0);
    assert_int_equal((long long)json_field_in(r.out, "motions", "count"), 2);
    assert_int_equal((long long)json_field_in(r.out, "motions", "first_colliding"), -1);
}

static void bad_options_are_usage_errors(void **state) {
    static cli_result r;
    char csv[512];
    (void)state;
    snprintf(csv, sizeof csv, "%s", write_text("two.csv", "slide\n0\n1\n"));
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --resolution 0", scene_map(), scene_urdf(), csv);
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--resolution"));
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --threads -1", scene_map(), scene_urdf(), csv);
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--threads"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(a_motion_through_the_wall_collides),
        cmocka_unit_test(a_path_short_of_the_wall_is_free),
        cmocka_unit_test(certified_motions),
        cmocka_unit_test(bad_options_are_usage_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
