/*
 * cli_check: `octoprox check` on a map and a URDF written by the test
 * gives the library's own answers (collision, exact distance, cost, and a
 * CSV path), exits 1 on collision, 2 on bad command lines and 3 on
 * missing or malformed files.
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

typedef struct library_answer {
    int collided;
    double distance, cost;
} library_answer;

static library_answer library_check(double slide, int32_t unknown_policy) {
    opx_octree *map = scene_load_map();
    opx_linkset *robot = scene_load_robot(slide);
    opx_query *query = NULL;
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    opx_distance_request distance_request = OPX_DISTANCE_REQUEST_INIT;
    opx_distance_result near = OPX_DISTANCE_RESULT_INIT;
    library_answer answer;
    request.unknown_policy = distance_request.unknown_policy = unknown_policy;
    request.compute_cost = 1;
    assert_int_equal(opx_query_create(NULL, &query), OPX_OK);
    assert_int_equal(opx_query_collide(query, map, robot, &request, &hit), OPX_OK);
    assert_int_equal(opx_query_distance(query, map, robot, &distance_request, &near), OPX_OK);
    answer.collided = hit.collided;
    answer.distance = near.distance;
    answer.cost = hit.total_cost;
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(map);
    return answer;
}

static void one_configuration_matches_the_library(void **state) {
    static const double slides[3] = {0.0, 1.85, 2.0};
    static cli_result r;
    int i, policy;
    (void)state;
    for (policy = 0; policy < 2; ++policy)
        for (i = 0; i < 3; ++i) {
            const library_answer expected = library_check(slides[i], policy);
            run_cli(&r, "check '%s' --urdf '%s' --joints slide=%.17g --distance --cost --unknown %s --json", scene_map(),
                    scene_urdf(), slides[i], policy ? "occupied" : "free");
            assert_int_equal(r.code, expected.collided ? 1 : 0);
            assert_int_equal(json_bool(r.out, "collided"), expected.collided);
            /* JSON numbers read back exactly. */
            assert_true(json_field_in(r.out, "distance", "distance") == expected.distance);
            assert_true(json_field(r.out, "total") == expected.cost);
        }
    /* The near miss is 5 cm (the wall's cells start at x = 2.0), the last one collides. */
    assert_true(library_check(1.85, 0).distance > 0.049 && library_check(1.85, 0).distance < 0.051);
    assert_int_equal(library_check(2.0, 0).collided, 1);
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=2", scene_map(), scene_urdf());
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "COLLISION"));
    assert_non_null(strstr(r.out, "colliding links: tool"));
}

static void a_csv_path_matches_the_library(void **state) {
    static const double slides[6] = {0.0, 0.5, 1.0, 1.5, 2.0, 2.5};
    static cli_result r;
    opx_octree *map = scene_load_map();
    opx_linkset *robot = scene_load_robot(0.0);
    opx_pose poses[6][2];
    opx_query *query = NULL;
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    opx_path_result expected = OPX_PATH_RESULT_INIT;
    const char *csv = write_text("path.csv", "# a slide towards the wall\nslide\n0\n0.5\n1.0\n\n1.5\n2.0\n2.5\n");
    int w, l;
    (void)state;
    for (w = 0; w < 6; ++w) {
        const char *name = "slide";
        assert_int_equal(opx_linkset_set_named_joint_positions(robot, &name, &slides[w], 1, NULL), OPX_OK);
        for (l = 0; l < 2; ++l) assert_int_equal(opx_linkset_get_pose(robot, (uint32_t)l, &poses[w][l]), OPX_OK);
    }
    request.compute_distance = 1;
    request.compute_cost = 1;
    assert_int_equal(opx_query_create(NULL, &query), OPX_OK);
    assert_int_equal(opx_query_path(query, map, robot, &poses[0][0], 6, 0, 0, &request, &expected), OPX_OK);
    assert_int_equal(expected.first_colliding_waypoint, 4);
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --distance --cost --json", scene_map(), scene_urdf(), csv);
    assert_int_equal(r.code, 1);
    assert_int_equal((long long)json_field(r.out, "waypoints"), 6);
    assert_int_equal((long long)json_field(r.out, "first_colliding_waypoint"), 4);
    assert_true(json_field(r.out, "min_distance") == expected.min_distance);
    assert_int_equal((long long)json_field(r.out, "min_distance_waypoint"), expected.min_distance_waypoint);
    assert_true(json_field(r.out, "total") == expected.total_cost);
    /* Stopping short of the wall: no collision, exit 0. */
    run_cli(&r, "check '%s' --urdf '%s' --path '%s'", scene_map(), scene_urdf(), write_text("short.csv", "slide\n0\n1\n1.8\n"));
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "3 waypoints"));
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    opx_octree_destroy(map);
}

static void expect_exit(int code, const char *message, const char *format, ...) {
    static cli_result r;
    char arguments[4096];
    va_list args;
    va_start(args, format);
    vsnprintf(arguments, sizeof arguments, format, args);
    va_end(args);
    run_cli(&r, "%s", arguments);
    if (r.code != code) fail_msg("'octoprox %s' exited %d, not %d; stderr: %s", arguments, r.code, code, r.err);
    if (strstr(r.err, message) == NULL) fail_msg("'octoprox %s': stderr \"%s\" lacks \"%s\"", arguments, r.err, message);
}

/* "a0=0,a1=0,...": count distinct joints. */
static const char *many_joints(int count) {
    static char text[4096];
    size_t n = 0;
    int i;
    for (i = 0; i < count && n < sizeof text; ++i)
        n += (size_t)snprintf(text + n, sizeof text - n, "%sa%x=0", i ? "," : "", (unsigned)i);
    return text;
}

static void bad_command_lines_exit_2(void **state) {
    const char *map = scene_map(), *urdf = scene_urdf();
    (void)state;
    expect_exit(2, "no map file given", "check --urdf '%s'", urdf);
    expect_exit(2, "no robot given", "check '%s'", map);
    expect_exit(2, "--unknown needs", "check '%s' --urdf '%s' --unknown maybe", map, urdf);
    expect_exit(2, "not name=value", "check '%s' --urdf '%s' --joints slide", map, urdf);
    expect_exit(2, "not name=value", "check '%s' --urdf '%s' --joints slide=fast", map, urdf);
    expect_exit(2, "elbow", "check '%s' --urdf '%s' --joints elbow=1", map, urdf);
    expect_exit(2, "--base-pose needs", "check '%s' --urdf '%s' --base-pose 1,2,3,4", map, urdf);
    expect_exit(2, "unknown option '--fast'", "check '%s' --urdf '%s' --fast", map, urdf);
    expect_exit(2, "--urdf needs", "check '%s' --urdf", map);
    expect_exit(2, "--joints names joint slide twice", "check '%s' --urdf '%s' --joints slide=1,slide=2", map, urdf);
    expect_exit(2, "--joints names more than 512 joints", "check '%s' --urdf '%s' --joints %s", map, urdf,
                many_joints(513));
}

/* A path whose one waypoint line is 70000 characters: "0000...0001". */
static const char *write_long_line_csv(void) {
    static char text[70100];
    size_t n = (size_t)snprintf(text, sizeof text, "slide\n");
    memset(text + n, '0', 69999);
    snprintf(text + n + 69999, sizeof text - n - 69999, "1\n");
    return write_text("longline.csv", text);
}

static void bad_files_exit_3(void **state) {
    const char *map = scene_map(), *urdf = scene_urdf();
    (void)state;
    expect_exit(3, "missing.bt", "check '%s' --urdf '%s'", scratch_path("missing.bt"), urdf);
    expect_exit(3, "missing.urdf", "check '%s' --urdf '%s'", map, scratch_path("missing.urdf"));
    expect_exit(3, "broken.urdf", "check '%s' --urdf '%s'", map, write_text("broken.urdf", "<robot name=\"x\"><link"));
    expect_exit(3, "nomesh.urdf", "check '%s' --urdf '%s'", map,
                write_text("nomesh.urdf", "<robot name=\"m\"><link name=\"a\"><collision><geometry>"
                                          "<mesh filename=\"package://nowhere/m.stl\"/></geometry></collision></link></robot>"));
    expect_exit(3, "bad.csv:3", "check '%s' --urdf '%s' --path '%s'", map, urdf, write_text("bad.csv", "slide\n0\nx\n"));
    expect_exit(3, "joint slide is named twice", "check '%s' --urdf '%s' --path '%s'", map, urdf,
                write_text("twice.csv", "slide,slide\n0,1\n"));
    expect_exit(3, "longline.csv:2: the line is longer than", "check '%s' --urdf '%s' --path '%s'", map, urdf,
                write_long_line_csv());
    expect_exit(3, "2 values", "check '%s' --urdf '%s' --path '%s'", map, urdf, write_text("wide.csv", "slide\n0,1\n"));
    expect_exit(3, "no waypoint", "check '%s' --urdf '%s' --path '%s'", map, urdf, write_text("empty.csv", "slide\n"));
    expect_exit(3, "elbow", "check '%s' --urdf '%s' --path '%s'", map, urdf, write_text("elbow.csv", "elbow\n1\n"));
    expect_exit(3, "cannot open", "check '%s' --urdf '%s' --path '%s'", map, urdf, scratch_path("none.csv"));
}

/* The wall's points lie at x = 2.05, in the middle of cells [2.0, 2.1]: the
 * tool sphere (r 0.1) at slide 1.92 reaches x = 2.02, into the cells but
 * short of the points.  A .opx map keeps the points' boxes; .bt does not. */
static void point_extents_from_an_opx_map(void **state) {
    static cli_result r;
    static char opx[512];
    (void)state;
    (void)scene_map(); /* writes wall.pcd */
    snprintf(opx, sizeof opx, "%s", scratch_path("wall.opx"));
    run_cli(&r, "ingest '%s' --res 0.1 -o '%s'", scratch_path("wall.pcd"), opx);
    assert_int_equal(r.code, 0);
    run_cli(&r, "info '%s' --json", opx);
    assert_int_equal(r.code, 0);
    assert_true(json_field(r.out, "occupied_with_point_extent") > 0);
    assert_true(json_field(r.out, "occupied_with_point_extent") == json_field_in(r.out, "leaves", "occupied"));
    run_cli(&r, "info '%s' --json", scene_map());
    assert_true(json_field(r.out, "occupied_with_point_extent") == 0);
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=1.92 --json", opx, scene_urdf());
    assert_int_equal(r.code, 1);
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=1.92 --obstacles point-extents --distance --json", opx,
            scene_urdf());
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "\"obstacles\": \"point-extents\""));
    assert_true(json_field_in(r.out, "distance", "distance") > 0.02);
    /* The .bt map keeps whole cells whatever the option. */
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=1.92 --obstacles point-extents", scene_map(), scene_urdf());
    assert_int_equal(r.code, 1);
    run_cli(&r, "check '%s' --urdf '%s' --obstacles points", opx, scene_urdf());
    assert_int_equal(r.code, 2);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(one_configuration_matches_the_library),
        cmocka_unit_test(a_csv_path_matches_the_library),
        cmocka_unit_test(bad_command_lines_exit_2),
        cmocka_unit_test(bad_files_exit_3),
        cmocka_unit_test(point_extents_from_an_opx_map),
    };
    return cmocka_run_group_tests_name("cli_check", tests, NULL, NULL);
}
