/*
 * cli_export: `octoprox export` writes every occupied cell as a cube (8
 * vertices, 6 quads) in OBJ and PLY, adds the robot's triangulated shapes
 * (a box: 8 vertices, 12 triangles; a sphere: 144 and 256), and marks the
 * colliding link (OBJ group colliding_<link>, red PLY vertices).
 */
#define _XOPEN_SOURCE 700 /* mknod, symlink */

#include "cli_run.h"
#include "cli_scene.h"

#include <errno.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <cmocka.h>

#define BOX_VERTICES 8
#define BOX_TRIANGLES 12
#define SPHERE_VERTICES 144 /* 9 rings of 16 */
#define SPHERE_TRIANGLES 256

static long long occupied_cells(void) {
    opx_octree *map = scene_load_map();
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    assert_int_equal(opx_octree_get_stats(map, &stats), OPX_OK);
    opx_octree_destroy(map);
    assert_true(stats.leaves_occupied > 100);
    return (long long)stats.leaves_occupied;
}

static void obj_holds_every_cell_and_the_robot(void **state) {
    static cli_result r;
    char obj[512], mtl[600];
    const long long cells = occupied_cells();
    (void)state;
    snprintf(obj, sizeof obj, "%s", scratch_path("cells.obj"));
    run_cli(&r, "export '%s' --obj '%s' --json", scene_map(), obj);
    assert_int_equal(r.code, 0);
    assert_int_equal((long long)json_field(r.out, "occupied"), cells);
    assert_int_equal(count_lines_with_prefix(obj, "v "), 8 * cells);
    assert_int_equal(count_lines_with_prefix(obj, "f "), 6 * cells);
    assert_int_equal(count_lines_with_prefix(obj, "g occupied"), 1);
    snprintf(mtl, sizeof mtl, "%s.mtl", obj);
    assert_int_equal(count_lines_with_prefix(mtl, "newmtl occupied"), 1);

    run_cli(&r, "export '%s' --obj '%s' --uncertain --urdf '%s' --joints slide=2 --json", scene_map(), obj, scene_urdf());
    assert_int_equal(r.code, 0);
    assert_non_null(strstr(r.out, "\"colliding_links\": [\"tool\"]"));
    assert_int_equal(count_lines_with_prefix(obj, "v "), 8 * cells + BOX_VERTICES + SPHERE_VERTICES);
    assert_int_equal(count_lines_with_prefix(obj, "f "), 6 * cells + BOX_TRIANGLES + SPHERE_TRIANGLES);
    assert_int_equal(count_lines_with_prefix(obj, "g colliding_tool"), 1);
    assert_int_equal(count_lines_with_prefix(obj, "g link_base"), 1);
    assert_int_equal((long long)json_field(r.out, "vertices"), 8 * cells + BOX_VERTICES + SPHERE_VERTICES);

    run_cli(&r, "export '%s' --obj '%s' --urdf '%s' --joints slide=1", scene_map(), obj, scene_urdf());
    assert_int_equal(r.code, 0);
    assert_int_equal(count_lines_with_prefix(obj, "g colliding_"), 0);
    assert_int_equal(count_lines_with_prefix(obj, "g link_tool"), 1);
}

/* Reads a PLY written by the tool: vertex and face counts from the header,
 * and how many vertices are red (220, 30, 30). */
static void read_ply(const char *path, long long *vertices, long long *faces, long long *red) {
    static char header[4096];
    FILE *file = fopen(path, "rb");
    char *end;
    long long v;
    unsigned char record[15];
    size_t n;
    assert_non_null(file);
    n = fread(header, 1, sizeof header - 1, file);
    header[n] = '\0';
    end = strstr(header, "end_header\n");
    assert_non_null(end);
    assert_non_null(strstr(header, "format binary_little_endian 1.0"));
    *vertices = strtoll(strstr(header, "element vertex ") + 15, NULL, 10);
    *faces = strtoll(strstr(header, "element face ") + 13, NULL, 10);
    fseek(file, (long)(end - header) + 11, SEEK_SET);
    *red = 0;
    for (v = 0; v < *vertices; ++v) {
        assert_int_equal(fread(record, 1, sizeof record, file), sizeof record);
        if (record[12] == 220 && record[13] == 30 && record[14] == 30) ++*red;
    }
    fclose(file);
}

static void ply_holds_cubes_or_points_and_red_colliding_links(void **state) {
    static cli_result r;
    char ply[512];
    const long long cells = occupied_cells();
    long long vertices, faces, red;
    (void)state;
    snprintf(ply, sizeof ply, "%s", scratch_path("cells.ply"));
    run_cli(&r, "export '%s' --ply '%s' --urdf '%s' --joints slide=2", scene_map(), ply, scene_urdf());
    assert_int_equal(r.code, 0);
    read_ply(ply, &vertices, &faces, &red);
    assert_int_equal(vertices, 8 * cells + BOX_VERTICES + SPHERE_VERTICES);
    assert_int_equal(faces, 6 * cells + BOX_TRIANGLES + SPHERE_TRIANGLES);
    assert_int_equal(red, SPHERE_VERTICES);

    run_cli(&r, "export '%s' --ply '%s' --points", scene_map(), ply);
    assert_int_equal(r.code, 0);
    read_ply(ply, &vertices, &faces, &red);
    assert_int_equal(vertices, cells);
    assert_int_equal(faces, 0);
    assert_int_equal(red, 0);
}

static void bad_exports_exit_2_or_3(void **state) {
    static cli_result r;
    (void)state;
    run_cli(&r, "export '%s'", scene_map());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "no output given"));
    run_cli(&r, "export '%s' --obj a.obj --ply b.ply", scene_map());
    assert_int_equal(r.code, 2);
    run_cli(&r, "export '%s' --obj a.obj --points", scene_map());
    assert_int_equal(r.code, 2);
    assert_non_null(strstr(r.err, "--points needs --ply"));
    run_cli(&r, "export '%s' --obj a.obj --joints slide=1", scene_map());
    assert_int_equal(r.code, 2);
    run_cli(&r, "export '%s' --obj /nonexistent-dir/a.obj", scene_map());
    assert_int_equal(r.code, 3);
    assert_non_null(strstr(r.err, "cannot be written"));
    run_cli(&r, "export '%s' --obj a.obj", scratch_path("missing.bt"));
    assert_int_equal(r.code, 3);
}

static long file_size(const char *path) {
    struct stat info;
    return stat(path, &info) == 0 ? (long)info.st_size : -1;
}

/* Meshes larger than the file size limit (ulimit -f 1: 512 bytes): an
 * I/O error, and no truncated mesh (nor its .mtl) is left behind. */
static void meshes_past_the_file_size_limit_exit_3(void **state) {
    static const char *const kinds[2] = {"obj", "ply"};
    static cli_result r;
    int i;
    (void)state;
    for (i = 0; i < 2; ++i) {
        char name[32], mesh[512], mtl[600];
        snprintf(name, sizeof name, "whole.%s", kinds[i]);
        snprintf(mesh, sizeof mesh, "%s", scratch_path(name));
        run_cli(&r, "export '%s' --%s '%s'", scene_map(), kinds[i], mesh);
        assert_int_equal(r.code, 0);
        if (file_size(mesh) <= 512) fail_msg("%s is only %ld bytes: it fits the limit", mesh, file_size(mesh));
        snprintf(name, sizeof name, "limited.%s", kinds[i]);
        snprintf(mesh, sizeof mesh, "%s", scratch_path(name));
        snprintf(mtl, sizeof mtl, "%s.mtl", mesh);
        run_cli_file_limit(&r, 1, "export '%s' --%s '%s'", scene_map(), kinds[i], mesh);
        if (r.code != 3) fail_msg("export --%s under ulimit -f 1 exited %d, not 3; stderr: %s", kinds[i], r.code, r.err);
        assert_non_null(strstr(r.err, "cannot be written"));
        assert_int_equal(file_size(mesh), -1);
        assert_int_equal(file_size(mtl), -1);
    }
}

/* The bytes of a file, in a static buffer of 1 MiB (NUL-terminated). */
static const char *file_text(const char *path) {
    static char text[1 << 20];
    FILE *file = fopen(path, "rb");
    size_t n;
    assert_non_null(file);
    n = fread(text, 1, sizeof text - 1, file);
    text[n] = '\0';
    fclose(file);
    return text;
}

/* A failed export to a device (a private copy of /dev/full, made where
 * mknod is allowed) keeps the device node and makes no material file. */
static void a_failed_export_keeps_the_device(void **state) {
    static cli_result r;
    char device[512], mtl[600];
    struct stat info;
    (void)state;
    snprintf(device, sizeof device, "%s", scratch_path("full"));
    snprintf(mtl, sizeof mtl, "%s.mtl", device);
    if (mknod(device, S_IFCHR | 0600, makedev(1, 7)) != 0) {
        print_message("no device node (mknod: %s): device case skipped\n", strerror(errno));
        return;
    }
    run_cli(&r, "export '%s' --obj '%s'", scene_map(), device);
    if (r.code != 3) fail_msg("export to a full device exited %d, not 3; stderr: %s", r.code, r.err);
    assert_int_equal(stat(device, &info), 0);
    assert_true(S_ISCHR(info.st_mode));
    assert_int_equal(file_size(mtl), -1);
    run_cli(&r, "export '%s' --ply '%s'", scene_map(), device);
    assert_int_equal(r.code, 3);
    assert_int_equal(stat(device, &info), 0);
    assert_true(S_ISCHR(info.st_mode));
    unlink(device);
}

/* A failed export (past ulimit -f) keeps the mesh written before, its
 * material file, and an output given as a link; no temporary is left. */
static void a_failed_export_keeps_the_previous_mesh_and_the_link(void **state) {
    static cli_result r;
    static char before[1 << 20], mtl_before[1 << 20];
    char mesh[512], mtl[600], link[512];
    struct stat info;
    (void)state;
    snprintf(mesh, sizeof mesh, "%s", scratch_path("kept.obj"));
    snprintf(mtl, sizeof mtl, "%s.mtl", mesh);
    snprintf(link, sizeof link, "%s", scratch_path("alias.obj"));
    run_cli(&r, "export '%s' --obj '%s'", scene_map(), mesh);
    assert_int_equal(r.code, 0);
    snprintf(before, sizeof before, "%s", file_text(mesh));
    snprintf(mtl_before, sizeof mtl_before, "%s", file_text(mtl));
    run_cli_file_limit(&r, 1, "export '%s' --obj '%s' --urdf '%s'", scene_map(), mesh, scene_urdf());
    if (r.code != 3) fail_msg("export under ulimit -f 1 exited %d, not 3; stderr: %s", r.code, r.err);
    assert_string_equal(file_text(mesh), before);
    assert_string_equal(file_text(mtl), mtl_before);

    unlink(link);
    assert_int_equal(symlink("kept.obj", link), 0);
    run_cli_file_limit(&r, 1, "export '%s' --obj '%s' --urdf '%s'", scene_map(), link, scene_urdf());
    assert_int_equal(r.code, 3);
    assert_int_equal(lstat(link, &info), 0);
    assert_true(S_ISLNK(info.st_mode));
    assert_string_equal(file_text(mesh), before);
    /* A good export through the link replaces the file it points to. */
    run_cli(&r, "export '%s' --obj '%s' --urdf '%s'", scene_map(), link, scene_urdf());
    assert_int_equal(r.code, 0);
    assert_int_equal(lstat(link, &info), 0);
    assert_true(S_ISLNK(info.st_mode));
    assert_true(count_lines_with_prefix(mesh, "g link_tool") == 1);
    assert_int_equal(scratch_files_starting(".kept.obj."), 0);
    assert_int_equal(scratch_files_starting(".alias.obj."), 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(obj_holds_every_cell_and_the_robot),
        cmocka_unit_test(ply_holds_cubes_or_points_and_red_colliding_links),
        cmocka_unit_test(bad_exports_exit_2_or_3),
        cmocka_unit_test(meshes_past_the_file_size_limit_exit_3),
        cmocka_unit_test(a_failed_export_keeps_the_device),
        cmocka_unit_test(a_failed_export_keeps_the_previous_mesh_and_the_link),
    };
    return cmocka_run_group_tests_name("cli_export", tests, NULL, NULL);
}
