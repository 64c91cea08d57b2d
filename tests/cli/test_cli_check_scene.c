/*
 * cli_check_scene: `octoprox check --scene FILE` adds a MoveIt planning
 * scene's objects (YAML or .scene text) to the check, with or without a
 * map: collision names the object, the distance is the library's own
 * (the nearer of the map and the objects), benchmark scenes in robowflex's
 * dialect read as the message's, a malformed scene exits 3
 * naming the file and the line, and --scene with --path is a usage error.
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

/* A crate 0.2 m wide centred at (1, 0, 0.5): in the tool's way at x 0.9 to
 * 1.1, before the wall at x = 2. */
static const char kCrateYaml[] =
    "name: crate\n"
    "world:\n"
    "  collision_objects:\n"
    "    - header: {frame_id: world}\n"
    "      id: crate\n"
    "      pose:\n"
    "        position: {x: 1.0, y: 0.0, z: 0.5}\n"
    "        orientation: {x: 0.0, y: 0.0, z: 0.0, w: 1.0}\n"
    "      primitives:\n"
    "        - type: 1\n"
    "          dimensions: [0.2, 0.2, 0.2]\n"
    "      operation: 0\n"
    "is_diff: false\n";

static const char kCrateScene[] =
    "crate\n* crate\n1 0 0.5\n0 0 0 1\n1\nbox\n0.2 0.2 0.2\n0 0 0\n0 0 0 1\n0 0 0 0\n0\n.\n";

static const char *crate_yaml(void) {
    static char path[512];
    snprintf(path, sizeof path, "%s", write_text("crate.yaml", kCrateYaml));
    return path;
}

static const char *map_path(void) {
    static char path[512];
    snprintf(path, sizeof path, "%s", scene_map());
    return path;
}

static const char *urdf_path(void) {
    static char path[512];
    snprintf(path, sizeof path, "%s", scene_urdf());
    return path;
}

/* The library's distance at slide = value, with the map or without. */
static opx_distance_result library_distance(double slide, int with_map) {
    opx_octree *map = with_map ? scene_load_map() : NULL;
    opx_linkset *robot = scene_load_robot(slide);
    opx_world *world = NULL;
    opx_query *query = NULL;
    opx_distance_result d = OPX_DISTANCE_RESULT_INIT;
    assert_int_equal(opx_world_load_scene_file(crate_yaml(), &world), OPX_OK);
    assert_int_equal(opx_query_create(NULL, &query), OPX_OK);
    assert_int_equal(opx_query_set_world(query, world), OPX_OK);
    assert_int_equal(opx_query_distance(query, map, robot, NULL, &d), OPX_OK);
    opx_query_destroy(query);
    opx_world_destroy(world);
    opx_linkset_destroy(robot);
    opx_octree_destroy(map);
    return d;
}

static void the_scene_alone(void **state) {
    static cli_result r;
    (void)state;
    run_cli(&r, "check --scene '%s' --urdf '%s' --joints slide=1.0 --json", crate_yaml(), urdf_path());
    assert_int_equal(r.code, 1);
    assert_int_equal(json_bool(r.out, "collided"), 1);
    assert_true(json_field(r.out, "scene_objects") == 1.0);
    assert_non_null(strstr(r.out, "\"map\": null"));
    assert_non_null(strstr(r.out, "\"object\": \"crate\""));
    run_cli(&r, "check --scene '%s' --urdf '%s' --joints slide=1.0", crate_yaml(), urdf_path());
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "object crate (shape 0)"));
    run_cli(&r, "check --scene '%s' --urdf '%s' --joints slide=0.5 --distance --json", crate_yaml(), urdf_path());
    assert_int_equal(r.code, 0);
    assert_true(json_field_in(r.out, "distance", "distance") == library_distance(0.5, 0).distance);
    assert_true(library_distance(0.5, 0).distance > 0.2999 && library_distance(0.5, 0).distance < 0.3001);
}

/* The nearer of the wall and the crate, as the library answers. */
static void the_scene_beside_the_map(void **state) {
    static cli_result r;
    static const double slides[2] = {1.6, 1.35};  /* the wall nearer, then the crate */
    int i;
    (void)state;
    for (i = 0; i < 2; ++i) {
        const opx_distance_result expected = library_distance(slides[i], 1);
        assert_int_equal(expected.object, i == 0 ? -1 : 0);
        run_cli(&r, "check '%s' --scene '%s' --urdf '%s' --joints slide=%.17g --distance --json", map_path(),
                crate_yaml(), urdf_path(), slides[i]);
        assert_int_equal(r.code, 0);
        assert_true(json_field_in(r.out, "distance", "distance") == expected.distance);
        assert_non_null(strstr(r.out, i == 0 ? "\"object\": null" : "\"object\": \"crate\""));
    }
    run_cli(&r, "check '%s' --scene '%s' --urdf '%s' --joints slide=1.35 --distance", map_path(), crate_yaml(),
            urdf_path());
    assert_non_null(strstr(r.out, "link tool to object crate"));
}

static void scene_text_files_too(void **state) {
    static cli_result r;
    (void)state;
    const char *scene = write_text("crate.scene", kCrateScene);
    run_cli(&r, "check --scene '%s' --urdf '%s' --joints slide=0.5 --distance --json", scene, urdf_path());
    assert_int_equal(r.code, 0);
    assert_true(json_field_in(r.out, "distance", "distance") == library_distance(0.5, 0).distance);
}

/* The crate as robowflex writes it (MotionBenchMaker's scenes). */
static void robowflex_scenes_too(void **state) {
    static cli_result r;
    (void)state;
    const char *scene = write_text("crate_robowflex.yaml",
                                   "world:\n  collision_objects:\n    - id: crate\n"
                                   "      pose: {position: [1.0, 0.0, 0.5], orientation: [0, 0, 0, 1]}\n"
                                   "      primitives: [{type: box, dimensions: [0.2, 0.2, 0.2]}]\n");
    run_cli(&r, "check --scene '%s' --urdf '%s' --joints slide=0.5 --distance --json", scene, urdf_path());
    assert_int_equal(r.code, 0);
    assert_true(json_field_in(r.out, "distance", "distance") == library_distance(0.5, 0).distance);
    const char *bad = write_text("bad_robowflex.yaml", "world:\n  collision_objects:\n    - id: crate\n"
                                                       "      primitives: [{type: torus, dimensions: [0.2]}]\n");
    run_cli(&r, "check --scene '%s' --urdf '%s'", bad, urdf_path());
    assert_int_equal(r.code, 3);
    assert_non_null(strstr(r.err, "bad_robowflex.yaml: line 4: world.collision_objects[0].primitives[0].type"));
}

static void bad_scenes_and_options(void **state) {
    static cli_result r;
    (void)state;
    const char *bad = write_text("bad.yaml", "world:\n  collision_objects:\n    - id: post\n      primitives:\n"
                                             "        - type: 3\n          dimensions: [0.7]\n");
    run_cli(&r, "check --scene '%s' --urdf '%s'", bad, urdf_path());
    assert_int_equal(r.code, 3);
    assert_non_null(strstr(r.err, "bad.yaml: line 6: world.collision_objects[0].primitives[0].dimensions"));
    run_cli(&r, "check --scene '%s' --urdf '%s'", write_text("room.txt", "x"), urdf_path());
    assert_int_equal(r.code, 3);
    const char *csv = write_text("path.csv", "slide\n0\n1\n");
    run_cli(&r, "check '%s' --scene '%s' --urdf '%s' --path '%s'", map_path(), crate_yaml(), urdf_path(), csv);
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--scene and --path"));
    run_cli(&r, "check --urdf '%s'", urdf_path());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--scene"));
    run_cli(&r, "check '%s' --urdf '%s' --scene", map_path(), urdf_path());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--scene needs a scene file"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_scene_alone),
        cmocka_unit_test(the_scene_beside_the_map),
        cmocka_unit_test(scene_text_files_too),
        cmocka_unit_test(robowflex_scenes_too),
        cmocka_unit_test(bad_scenes_and_options),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
