/* The scene of the check and export tests: see cli_scene.h. */
#define _POSIX_C_SOURCE 200809L

#include "cli_scene.h"

#include "cli_run.h"

#include <octoprox/robot.h>

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

static const char kUrdf[] =
    "<?xml version=\"1.0\"?>\n"
    "<robot name=\"slider\">\n"
    "  <link name=\"base\"><collision><geometry><box size=\"0.2 0.2 0.2\"/></geometry></collision></link>\n"
    "  <link name=\"tool\"><collision><geometry><sphere radius=\"0.1\"/></geometry></collision></link>\n"
    "  <joint name=\"slide\" type=\"prismatic\"><parent link=\"base\"/><child link=\"tool\"/>\n"
    "    <origin xyz=\"0 0 0.5\"/><axis xyz=\"1 0 0\"/>\n"
    "    <limit lower=\"0\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>\n"
    "</robot>\n";

const char *scene_map(void) {
    static char map[512] = "";
    static char text[1 << 16];
    static cli_result r;
    size_t n;
    int i, j;
    if (map[0] != '\0') return map;
    n = (size_t)snprintf(text, sizeof text, "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
                                            "WIDTH %d\nHEIGHT 1\nPOINTS %d\nDATA ascii\n", 21 * 21, 21 * 21);
    for (i = 0; i < 21; ++i)
        for (j = 0; j < 21; ++j)
            n += (size_t)snprintf(text + n, sizeof text - n, "2.05 %.3f %.3f\n", -1.0 + 0.1 * i, -0.5 + 0.1 * j);
    write_bytes("wall.pcd", text, n);
    snprintf(map, sizeof map, "%s", scratch_path("wall.bt"));
    run_cli(&r, "ingest '%s' --res 0.1 -o '%s'", scratch_path("wall.pcd"), map);
    if (r.code != 0) fail_msg("ingest failed: %s", r.err);
    return map;
}

const char *scene_urdf(void) {
    static char path[512];
    snprintf(path, sizeof path, "%s", write_text("slider.urdf", kUrdf));
    return path;
}

opx_octree *scene_load_map(void) {
    opx_octree *tree = NULL;
    assert_int_equal(opx_octree_load_file(scene_map(), NULL, &tree), OPX_OK);
    return tree;
}

opx_linkset *scene_load_robot(double slide) {
    const char *name = "slide";
    opx_linkset *links = NULL;
    assert_int_equal(opx_linkset_load_urdf_string(kUrdf, NULL, &links), OPX_OK);
    assert_int_equal(opx_linkset_set_named_joint_positions(links, &name, &slide, 1, NULL), OPX_OK);
    return links;
}
