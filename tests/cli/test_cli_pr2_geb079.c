/*
 * cli_pr2_geb079 (acceptance): `octoprox check` on the real map geb079.bt
 * with the PR2 at its zero configuration, standing in the building's
 * corridor, gives the same answer as the library called directly: the
 * collided flag and the distance (to 1e-9 m), with unknown space free and
 * with it occupied.
 *
 * The pose: base_footprint at (12.0, -0.1, 0.0), yaw 0 (facing +x, along
 * the corridor).  It was chosen by scanning the corridor (y in [-1, 1])
 * for base positions where the PR2 at zero collides with nothing; there
 * the corridor's walls are about 1.2 m to either side and the closest
 * obstacle is the floor under the casters (4.4 mm).
 *
 * Needs the shared data ($OPX_DATA_DIR or ../shared/data): exits 77
 * (skipped) without it.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "opx_data_test.h"

#include <octoprox/octoprox.h>
#include <octoprox/robot.h>

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <cmocka.h>

#define BASE_POSE_ARG "12.0,-0.1,0.0"
static const opx_pose kBasePose = {{12.0, -0.1, 0.0}, {0.0, 0.0, 0.0, 1.0}};

static char g_map[4096], g_urdf[4096], g_package[4200];

static void find_data(void) {
    const char *env = getenv("OPX_DATA_DIR");
    const char *dir = env != NULL && env[0] != '\0' ? env : OPX_DEFAULT_DATA_DIR;
    struct stat info;
    snprintf(g_map, sizeof g_map, "%s/maps/geb079.bt", dir);
    snprintf(g_urdf, sizeof g_urdf, "%s/robots/pr2_description/urdf/robot.xml", dir);
    snprintf(g_package, sizeof g_package, "moveit_resources_pr2_description=%s/robots/pr2_description", dir);
    if (stat(g_map, &info) != 0) exit_without_data(g_map);
    if (stat(g_urdf, &info) != 0) exit_without_data(g_urdf);
}

typedef struct answer {
    int collided;
    double distance;
} answer;

/* The library's answer for the PR2 at zero joints at kBasePose. */
static answer library_answer(int32_t unknown_policy) {
    const char *dirs[1] = {g_package};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    opx_octree *map = NULL;
    opx_linkset *pr2 = NULL;
    opx_query *query = NULL;
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    opx_distance_request distance_request = OPX_DISTANCE_REQUEST_INIT;
    opx_distance_result near = OPX_DISTANCE_RESULT_INIT;
    double *zeros;
    uint32_t joints = 0;
    answer a;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    assert_int_equal(opx_octree_load_file(g_map, NULL, &map), OPX_OK);
    assert_int_equal(opx_linkset_load_urdf_file(g_urdf, &options, &pr2), OPX_OK);
    assert_int_equal(opx_linkset_get_joint_count(pr2, &joints), OPX_OK);
    zeros = calloc(joints + 1, sizeof *zeros);
    assert_int_equal(opx_linkset_set_joint_positions(pr2, zeros, joints, &kBasePose), OPX_OK);
    request.unknown_policy = distance_request.unknown_policy = unknown_policy;
    assert_int_equal(opx_query_create(NULL, &query), OPX_OK);
    assert_int_equal(opx_query_collide(query, map, pr2, &request, &hit), OPX_OK);
    assert_int_equal(opx_query_distance(query, map, pr2, &distance_request, &near), OPX_OK);
    a.collided = hit.collided;
    a.distance = near.distance;
    free(zeros);
    opx_query_destroy(query);
    opx_linkset_destroy(pr2);
    opx_octree_destroy(map);
    return a;
}

static void check_matches_library(int32_t unknown_policy) {
    static cli_result r;
    const answer expected = library_answer(unknown_policy);
    run_cli(&r, "check '%s' --urdf '%s' --package-dir '%s' --base-pose " BASE_POSE_ARG " --distance --unknown %s --json",
            g_map, g_urdf, g_package, unknown_policy == OPX_UNKNOWN_OCCUPIED ? "occupied" : "free");
    printf("unknown %s: library collided %d distance %.12f; tool exit %d\n",
           unknown_policy == OPX_UNKNOWN_OCCUPIED ? "occupied" : "free", expected.collided, expected.distance, r.code);
    assert_int_equal(r.code, expected.collided ? 1 : 0);
    assert_int_equal(json_bool(r.out, "collided"), expected.collided);
    assert_true(fabs(json_field_in(r.out, "distance", "distance") - expected.distance) <= 1e-9);
    assert_int_equal((long long)json_field(r.out, "links"), 95);
}

static void zero_configuration_in_the_corridor(void **state) {
    const answer free_space = library_answer(OPX_UNKNOWN_FREE);
    (void)state;
    /* The pose is in free space of the corridor, a few millimetres above the floor. */
    assert_int_equal(free_space.collided, 0);
    assert_true(free_space.distance > 0.0 && free_space.distance < 0.05);
    check_matches_library(OPX_UNKNOWN_FREE);
}

static void zero_configuration_with_unknown_space_occupied(void **state) {
    (void)state;
    check_matches_library(OPX_UNKNOWN_OCCUPIED);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(zero_configuration_in_the_corridor),
        cmocka_unit_test(zero_configuration_with_unknown_space_occupied),
    };
    find_data();
    return cmocka_run_group_tests_name("cli_pr2_geb079", tests, NULL, NULL);
}
