/*
 * cli_check_robot: the robot options of `octoprox check`: --padding grows
 * every link (a near miss becomes a collision), --disable-link takes a
 * link out of the queries, --srdf reports the SRDF's disabled pairs, and
 * package:// meshes are found through --package-dir, $ROS_PACKAGE_PATH (a
 * package folder, a folder of packages, a package.xml naming a folder
 * named otherwise) and $AMENT_PREFIX_PATH (PREFIX/share/NAME), the
 * explicit option first.
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
#include <sys/stat.h>

#include <cmocka.h>

/* The slider's tool as a mesh from a package: a cube of half edge `half`
 * around the tool's origin (0.5 m up, `slide` along x). */
static const char kMeshUrdf[] =
    "<?xml version=\"1.0\"?>\n"
    "<robot name=\"slider\">\n"
    "  <link name=\"base\"><collision><geometry><box size=\"0.2 0.2 0.2\"/></geometry></collision></link>\n"
    "  <link name=\"tool\"><collision><geometry><mesh filename=\"package://tool_pkg/meshes/tool.stl\"/>"
    "</geometry></collision></link>\n"
    "  <joint name=\"slide\" type=\"prismatic\"><parent link=\"base\"/><child link=\"tool\"/>\n"
    "    <origin xyz=\"0 0 0.5\"/><axis xyz=\"1 0 0\"/>\n"
    "    <limit lower=\"0\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>\n"
    "</robot>\n";

static void make_dir(const char *relative) {
    const char *path = scratch_path(relative);
    if (mkdir(path, 0700) != 0) fail_msg("cannot make %s", path);
}

/* An ASCII STL cube of half edge `half` at scratch_dir()/relative. */
static void write_cube_stl(const char *relative, double half) {
    static const int faces[12][3] = {{0, 1, 3}, {0, 3, 2}, {4, 6, 7}, {4, 7, 5}, {0, 4, 5}, {0, 5, 1},
                                     {2, 3, 7}, {2, 7, 6}, {0, 2, 6}, {0, 6, 4}, {1, 5, 7}, {1, 7, 3}};
    static char text[8192];
    size_t n = (size_t)snprintf(text, sizeof text, "solid cube\n");
    int f, k;
    for (f = 0; f < 12; ++f) {
        n += (size_t)snprintf(text + n, sizeof text - n, "facet normal 0 0 0\nouter loop\n");
        for (k = 0; k < 3; ++k) {
            const int v = faces[f][k];
            n += (size_t)snprintf(text + n, sizeof text - n, "vertex %g %g %g\n", v & 4 ? half : -half,
                                  v & 2 ? half : -half, v & 1 ? half : -half);
        }
        n += (size_t)snprintf(text + n, sizeof text - n, "endloop\nendfacet\n");
    }
    snprintf(text + n, sizeof text - n, "endsolid cube\n");
    write_text(relative, text);
}

static void padding_turns_a_near_miss_into_a_collision(void **state) {
    static cli_result r;
    (void)state;
    /* The tool's sphere misses the wall by 5 cm at slide 1.85. */
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=1.85 --padding 0.04 --json", scene_map(), scene_urdf());
    assert_int_equal(r.code, 0);
    assert_true(json_field(r.out, "padding") == 0.04);
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=1.85 --padding=0.06", scene_map(), scene_urdf());
    assert_int_equal(r.code, 1);
    assert_non_null(strstr(r.out, "padding    0.06 m"));
    run_cli(&r, "check '%s' --urdf '%s' --padding -1", scene_map(), scene_urdf());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--padding"));
}

static void a_disabled_link_takes_part_in_no_query(void **state) {
    static cli_result r;
    (void)state;
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=2 --disable-link tool --json", scene_map(), scene_urdf());
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "\"disabled_links\": [\"tool\"]"));
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=2 --disable-link base", scene_map(), scene_urdf());
    assert_int_equal(r.code, 1);
    run_cli(&r, "check '%s' --urdf '%s' --disable-link gripper", scene_map(), scene_urdf());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "no link named 'gripper'"));
}

static void the_srdf_pairs_are_reported(void **state) {
    static cli_result r;
    const char *srdf = write_text("slider.srdf", "<?xml version=\"1.0\"?>\n<robot name=\"slider\">\n"
                                                 "  <disable_collisions link1=\"base\" link2=\"tool\" reason=\"Adjacent\"/>\n"
                                                 "</robot>\n");
    char path[512];
    (void)state;
    snprintf(path, sizeof path, "%s", srdf);
    run_cli(&r, "check '%s' --urdf '%s' --srdf '%s' --json", scene_map(), scene_urdf(), path);
    assert_int_equal(r.code, 0);
    assert_int_equal((int)json_field(r.out, "srdf_disabled_pairs"), 1);
    run_cli(&r, "check '%s' --urdf '%s' --srdf '%s'", scene_map(), scene_urdf(), write_text("bad.srdf", "<robot"));
    assert_int_equal(r.code, 3);
    assert_non_null(strstr(r.err, "bad.srdf"));
}

/* A check of the mesh slider at slide 1.85: exit 0 with a small tool
 * mesh, 1 with a big one, 3 when the package is not found. */
static int check_mesh_robot(const char *urdf, const char *options) {
    static cli_result r;
    run_cli(&r, "check '%s' --urdf '%s' --joints slide=1.85 %s", scene_map(), urdf, options);
    if (r.code == 3) assert_non_null(strstr(r.err, "tool_pkg"));
    return r.code;
}

static void package_meshes_are_found_in_the_environment(void **state) {
    char urdf[512], small[512], big[512];
    (void)state;
    make_dir("small"), make_dir("small/tool_pkg"), make_dir("small/tool_pkg/meshes");
    make_dir("big"), make_dir("big/renamed"), make_dir("big/renamed/meshes");
    make_dir("prefix"), make_dir("prefix/share"), make_dir("prefix/share/tool_pkg"),
        make_dir("prefix/share/tool_pkg/meshes");
    write_cube_stl("small/tool_pkg/meshes/tool.stl", 0.05);
    write_cube_stl("big/renamed/meshes/tool.stl", 0.2);
    write_cube_stl("prefix/share/tool_pkg/meshes/tool.stl", 0.2);
    write_text("big/renamed/package.xml", "<?xml version=\"1.0\"?>\n<package format=\"2\">\n"
                                          "  <name> tool_pkg </name>\n  <version>1.0.0</version>\n</package>\n");
    snprintf(urdf, sizeof urdf, "%s", write_text("mesh_slider.urdf", kMeshUrdf));
    snprintf(small, sizeof small, "%s", scratch_path("small"));
    snprintf(big, sizeof big, "%s", scratch_path("big"));
    unsetenv("ROS_PACKAGE_PATH"), unsetenv("AMENT_PREFIX_PATH");
    assert_int_equal(check_mesh_robot(urdf, ""), 3);
    assert_int_equal(check_mesh_robot(urdf, "--package-dir tool_pkg=/nonexistent"), 3);
    /* A folder of packages, the package folder itself, a package.xml's name. */
    setenv("ROS_PACKAGE_PATH", small, 1);
    assert_int_equal(check_mesh_robot(urdf, ""), 0);
    setenv("ROS_PACKAGE_PATH", scratch_path("small/tool_pkg"), 1);
    assert_int_equal(check_mesh_robot(urdf, ""), 0);
    setenv("ROS_PACKAGE_PATH", big, 1);
    assert_int_equal(check_mesh_robot(urdf, ""), 1);
    setenv("ROS_PACKAGE_PATH", scratch_path("big/renamed"), 1);
    assert_int_equal(check_mesh_robot(urdf, ""), 1);
    /* Empty items and missing folders are skipped; the first folder wins. */
    {
        char list[2048];
        snprintf(list, sizeof list, "::/nonexistent:%s:%s", small, big);
        setenv("ROS_PACKAGE_PATH", list, 1);
        assert_int_equal(check_mesh_robot(urdf, ""), 0);
    }
    /* --package-dir is tried first. */
    {
        char option[700];
        snprintf(option, sizeof option, "--package-dir tool_pkg=%s/renamed", big);
        setenv("ROS_PACKAGE_PATH", small, 1);
        assert_int_equal(check_mesh_robot(urdf, option), 1);
    }
    unsetenv("ROS_PACKAGE_PATH");
    setenv("AMENT_PREFIX_PATH", scratch_path("prefix"), 1);
    assert_int_equal(check_mesh_robot(urdf, ""), 1);
    unsetenv("AMENT_PREFIX_PATH");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(padding_turns_a_near_miss_into_a_collision),
        cmocka_unit_test(a_disabled_link_takes_part_in_no_query),
        cmocka_unit_test(the_srdf_pairs_are_reported),
        cmocka_unit_test(package_meshes_are_found_in_the_environment),
    };
    unsetenv("ROS_PACKAGE_PATH");
    unsetenv("AMENT_PREFIX_PATH");
    return cmocka_run_group_tests_name("cli_check_robot", tests, NULL, NULL);
}
