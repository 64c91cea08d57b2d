/*
 * cli_inputs: inputs the tool refuses, and how.  Endless devices are no
 * map (exit 3, at once); a cloud, a scene or a YAML nesting beyond the
 * readers' bounds is a bad input (exit 3, the reader's message); list
 * items that are empty or not decimal numbers, and a path resolution that
 * gives too many steps, are usage errors (exit 2, naming the item).
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "cli_scene.h"

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <cmocka.h>

static void expect_exit(const cli_result *r, int code, const char *message) {
    if (r->code != code) fail_msg("exited %d, not %d; stderr: %s", r->code, code, r->err);
    if (strstr(r->err, message) == NULL) fail_msg("stderr lacks \"%s\": %s", message, r->err);
}

/* `octoprox info DEVICE` exits 3 naming no map, within a second. */
static void info_refuses_at_once(const char *device) {
    static cli_result r;
    struct timespec start, end;
    double seconds;
    clock_gettime(CLOCK_MONOTONIC, &start);
    run_cli(&r, "info %s", device);
    clock_gettime(CLOCK_MONOTONIC, &end);
    expect_exit(&r, 3, "not an OctoMap file");
    seconds = (double)(end.tv_sec - start.tv_sec) + 1e-9 * (double)(end.tv_nsec - start.tv_nsec);
    if (seconds > 1.0) fail_msg("info %s took %.2f s", device, seconds);
}

static void endless_devices_are_no_map(void **state) {
    (void)state;
    info_refuses_at_once("/dev/zero");
    info_refuses_at_once("/dev/urandom");
}

/* WIDTH x HEIGHT beyond what any machine holds: a corrupt header. */
static void a_pcd_beyond_the_point_cap_is_a_bad_input(void **state) {
    static cli_result r;
    const char *cloud = write_text("huge.pcd", "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                               "WIDTH 4294967295\nHEIGHT 4294967295\nDATA ascii\n1 2 3\n");
    (void)state;
    run_cli(&r, "ingest '%s' -o '%s'", cloud, scratch_path("huge.bt"));
    expect_exit(&r, 3, "more than this machine can hold");
}

static void scene_sizes_beyond_a_thousand_km_are_refused(void **state) {
    static cli_result r;
    const char *yaml = write_text("huge.yaml", "world:\n  collision_objects:\n    - id: huge\n"
                                               "      primitives: [{type: 3, dimensions: [1e200, 1e200]}]\n");
    const char *text = write_text("far.scene", "far\n* far\n2e6 0 0\n0 0 0 1\n1\nsphere\n0.1\n0 0 0\n0 0 0 1\n"
                                               "0 0 0 0\n0\n.\n");
    (void)state;
    run_cli(&r, "check --scene '%s' --urdf '%s'", yaml, scene_urdf());
    expect_exit(&r, 3, "at most 1e+06 m");
    run_cli(&r, "check --scene '%s' --urdf '%s'", text, scene_urdf());
    expect_exit(&r, 3, "within +-1e+06 m");
}

static void yaml_nested_too_deep_says_so(void **state) {
    static char yaml[4096];
    static cli_result r;
    const int depth = 1000;
    int i;
    (void)state;
    snprintf(yaml, sizeof yaml, "world:\n  collision_objects:\n    - id: deep\n      primitives: ");
    for (i = 0; i < depth; ++i) strcat(yaml, "[");
    for (i = 0; i < depth; ++i) strcat(yaml, "]");
    strcat(yaml, "\n");
    run_cli(&r, "check --scene '%s' --urdf '%s'", write_text("deep.yaml", yaml), scene_urdf());
    expect_exit(&r, 3, "nested 500 levels deep or more");
}

/* Each --joints value is refused, the message naming the item. */
static void bad_joint_lists_are_usage_errors(void **state) {
    static const char *const cases[][2] = {
        {",", "item 1 is empty"},
        {"slide=1,,", "item 2 is empty"},
        {"", "item 1 is empty"},
        {"slide=0x10", "item 1 'slide=0x10'"},
        {"slide=1,slide=2", "twice"},
        {"slide= 1", "item 1 'slide= 1'"},
        {"slide=1e", "item 1 'slide=1e'"},
        {"slide=.", "item 1 'slide=.'"},
    };
    static cli_result r;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        run_cli(&r, "check '%s' --urdf '%s' --joints '%s'", scene_map(), scene_urdf(), cases[i][0]);
        expect_exit(&r, 2, cases[i][1]);
    }
    run_cli(&r, "check '%s' --urdf '%s' --joints 'slide=-1.5e-1'", scene_map(), scene_urdf());
    assert_int_equal(r.code, 0);
}

static void non_decimal_numbers_are_usage_errors(void **state) {
    static const char *const options[] = {"--base-pose 0x1,0,0", "--base-pose 1,,0", "--padding 0x0.1",
                                          "--padding ' 0.1'",    "--padding inf",    "--base-pose 1,2,3,"};
    static cli_result r;
    size_t i;
    (void)state;
    for (i = 0; i < sizeof options / sizeof options[0]; ++i) {
        run_cli(&r, "check '%s' --urdf '%s' %s", scene_map(), scene_urdf(), options[i]);
        expect_exit(&r, 2, "decimal");
    }
    run_cli(&r, "check '%s' --urdf '%s' --path x.csv --threads ' 1'", scene_map(), scene_urdf());
    expect_exit(&r, 2, "--threads");
}

/* A resolution that cuts a motion into more steps than are checked. */
static void a_resolution_of_too_many_steps_is_a_usage_error(void **state) {
    static cli_result r;
    const char *path = write_text("far.csv", "slide\n0\n1\n");
    (void)state;
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --resolution 1e-9", scene_map(), scene_urdf(), path);
    expect_exit(&r, 2, "--resolution 1e-09 cuts motion 0");
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --resolution 0x1p-4", scene_map(), scene_urdf(), path);
    expect_exit(&r, 2, "--resolution");
    run_cli(&r, "check '%s' --urdf '%s' --path '%s' --resolution 1e-3", scene_map(), scene_urdf(), path);
    assert_true(r.code == 0 || r.code == 1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(endless_devices_are_no_map),
        cmocka_unit_test(a_pcd_beyond_the_point_cap_is_a_bad_input),
        cmocka_unit_test(scene_sizes_beyond_a_thousand_km_are_refused),
        cmocka_unit_test(yaml_nested_too_deep_says_so),
        cmocka_unit_test(bad_joint_lists_are_usage_errors),
        cmocka_unit_test(non_decimal_numbers_are_usage_errors),
        cmocka_unit_test(a_resolution_of_too_many_steps_is_a_usage_error),
    };
    return cmocka_run_group_tests_name("cli_inputs", tests, NULL, NULL);
}
