/*
 * cli_check_self: `octoprox check --self` gives the library's own
 * self-collision and self-distance answers, with and without a map, skips
 * the SRDF's pairs, checks every waypoint of a --path, and refuses the
 * options that need a map when none is given.
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

/* base: a box on the floor (top at z = 0.2); arm: a cylinder lying on it
 * (z 0.15 to 0.25, x 0 to 0.6), turning about z (shoulder); hand: a
 * sphere 0.3 m above the arm's end, sliding along it (slide); flap: a box
 * below the hand (z 0.35 to 0.45) that the joint "drop" lowers towards
 * the arm's end. */
static const char kArm[] =
    "<robot name=\"arm\">\n"
    " <link name=\"base\"><collision><origin xyz=\"0 0 0.1\"/><geometry><box size=\"0.4 0.4 0.2\"/></geometry>"
    "</collision></link>\n"
    " <link name=\"arm\"><collision><origin xyz=\"0.3 0 0\" rpy=\"0 1.5707963267948966 0\"/>"
    "<geometry><cylinder radius=\"0.05\" length=\"0.6\"/></geometry></collision></link>\n"
    " <link name=\"hand\"><collision><origin xyz=\"0 0 0.3\"/><geometry><sphere radius=\"0.05\"/></geometry>"
    "</collision></link>\n"
    " <link name=\"flap\"><collision><origin xyz=\"0 0 0.2\"/><geometry><box size=\"0.1 0.1 0.1\"/></geometry>"
    "</collision></link>\n"
    " <joint name=\"shoulder\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/>"
    "<origin xyz=\"0 0 0.2\"/><axis xyz=\"0 0 1\"/><limit lower=\"-1.5\" upper=\"1.5\" velocity=\"1\" effort=\"1\"/>"
    "</joint>\n"
    " <joint name=\"slide\" type=\"prismatic\"><parent link=\"arm\"/><child link=\"hand\"/>"
    "<origin xyz=\"0.6 0 0\"/><axis xyz=\"1 0 0\"/><limit lower=\"0\" upper=\"0.2\" velocity=\"1\" effort=\"1\"/>"
    "</joint>\n"
    " <joint name=\"drop\" type=\"prismatic\"><parent link=\"hand\"/><child link=\"flap\"/>"
    "<origin xyz=\"0 0 0\"/><axis xyz=\"0 0 -1\"/><limit lower=\"0\" upper=\"0.2\" velocity=\"1\" effort=\"1\"/>"
    "</joint>\n"
    "</robot>\n";

static const char kSrdf[] =
    "<robot name=\"arm\"><disable_collisions link1=\"base\" link2=\"arm\" reason=\"Adjacent\"/>"
    "<disable_collisions link1=\"hand\" link2=\"flap\" reason=\"Adjacent\"/></robot>\n";

/* The paths are copied: write_text's buffers are reused (scene_map()
 * writes files too). */
static const char *arm_urdf(void) {
    static char path[512];
    snprintf(path, sizeof path, "%s", write_text("arm.urdf", kArm));
    return path;
}

static const char *arm_srdf(void) {
    static char path[512];
    snprintf(path, sizeof path, "%s", write_text("arm.srdf", kSrdf));
    return path;
}

static const char *map_path(void) {
    static char path[512];
    snprintf(path, sizeof path, "%s", scene_map());
    return path;
}

/* The library's self-distance of the arm with the SRDF at drop = value. */
static double library_self_distance(double drop) {
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    opx_linkset *robot = NULL;
    opx_query *query = NULL;
    opx_self_distance_result d = OPX_SELF_DISTANCE_RESULT_INIT;
    const char *name = "drop";
    options.srdf_path = arm_srdf();
    assert_int_equal(opx_linkset_load_urdf_string(kArm, &options, &robot), OPX_OK);
    assert_int_equal(opx_linkset_set_named_joint_positions(robot, &name, &drop, 1, NULL), OPX_OK);
    assert_int_equal(opx_query_create(NULL, &query), OPX_OK);
    assert_int_equal(opx_query_self_distance(query, robot, NULL, &d), OPX_OK);
    opx_query_destroy(query);
    opx_linkset_destroy(robot);
    return d.distance;
}

/* The flap hangs 0.1 m above the arm's top (z 0.25 vs 0.35 at drop 0)
 * and reaches into it at drop 0.15. */
static void self_answers_match_the_library(void **state) {
    static cli_result r;
    const char *urdf = arm_urdf(), *srdf = arm_srdf();
    (void)state;
    run_cli(&r, "check --self --urdf '%s' --srdf '%s' --distance --json", urdf, srdf);
    assert_int_equal(r.code, 0);
    assert_int_equal(json_bool(r.out, "collided"), 0);
    assert_non_null(strstr(r.out, "\"map\": null"));
    assert_true(json_field_in(r.out, "self_distance", "distance") == library_self_distance(0.0));
    assert_non_null(strstr(r.out, "\"link_a\": \"arm\", \"link_b\": \"flap\""));
    run_cli(&r, "check --self --urdf '%s' --srdf '%s' --joints drop=0.15 --distance", urdf, srdf);
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "arm - flap"));
    assert_non_null(strstr(r.out, "COLLISION"));
    assert_true(library_self_distance(0.15) == 0.0);
}

/* Without the SRDF the arm lying on the base collides; with it, not. */
static void the_srdf_pairs_are_skipped(void **state) {
    static cli_result r;
    const char *urdf = arm_urdf();
    (void)state;
    run_cli(&r, "check --self --urdf '%s' --json", urdf);
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "\"link_a\": \"base\", \"link_b\": \"arm\""));
    assert_int_equal((long long)json_field_in(r.out, "self", "checked_pairs"), 6);
    run_cli(&r, "check --self --urdf '%s' --srdf '%s' --json", urdf, arm_srdf());
    assert_int_equal(r.code, 0);
    assert_int_equal((long long)json_field_in(r.out, "self", "checked_pairs"), 4);
}

/* With a map: the map's answer and the robot's own; the wall of the scene
 * is 2 m away from this arm, so only --self decides. */
static void with_a_map_both_are_checked(void **state) {
    static cli_result r;
    (void)state;
    run_cli(&r, "check '%s' --self --urdf '%s' --srdf '%s' --joints drop=0.15", map_path(), arm_urdf(), arm_srdf());
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "colliding links: none"));
    assert_non_null(strstr(r.out, "arm - flap"));
    run_cli(&r, "check '%s' --urdf '%s' --srdf '%s' --joints drop=0.15", map_path(), arm_urdf(), arm_srdf());
    assert_int_equal(r.code, 0);
}

/* --path --self: a waypoint lowering the flap into the arm collides. */
static void a_path_checks_every_waypoint_against_itself(void **state) {
    static cli_result r;
    char csv[512];
    (void)state;
    snprintf(csv, sizeof csv, "%s", write_text("drop.csv", "drop\n0\n0.05\n0.15\n0.05\n"));
    run_cli(&r, "check '%s' --self --urdf '%s' --srdf '%s' --path '%s' --json", map_path(), arm_urdf(), arm_srdf(),
            csv);
    assert_int_equal(r.code, 1);
    assert_int_equal((long long)json_field(r.out, "first_colliding_waypoint"), 2);
    run_cli(&r, "check '%s' --urdf '%s' --srdf '%s' --path '%s'", map_path(), arm_urdf(), arm_srdf(), csv);
    assert_int_equal(r.code, 0);
}

static void options_needing_a_map_exit_2(void **state) {
    static cli_result r;
    (void)state;
    run_cli(&r, "check --self --urdf '%s' --path p.csv", arm_urdf());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--path and --cost need a map file"));
    run_cli(&r, "check --self --urdf '%s' --cost", arm_urdf());
    assert_int_equal(r.code, 2);
    run_cli(&r, "check --urdf '%s'", arm_urdf());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "no map file given (or --self)"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(self_answers_match_the_library),
        cmocka_unit_test(the_srdf_pairs_are_skipped),
        cmocka_unit_test(with_a_map_both_are_checked),
        cmocka_unit_test(a_path_checks_every_waypoint_against_itself),
        cmocka_unit_test(options_needing_a_map_exit_2),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
