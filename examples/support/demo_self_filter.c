/* The demo's self-filter step: see demo_self_filter.h. */
#include "demo_self_filter.h"

#include "demo_queries.h"
#include "shape_mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* One of the two maps: the composite ingested without or with the filter. */
typedef struct filtered_map {
    opx_octree *map;
    opx_insert_report report;
    opx_octree_stats stats;
    double ms;
    int collides;
    size_t cells_hit; /* distinct cells the robot touches */
} filtered_map;

static int failed(opx_status status, const char *what) {
    if (status == OPX_OK) return 0;
    fprintf(stderr, "opx-demo: %s failed: %s (%s)\n", what, opx_status_name(status), opx_last_error());
    return -1;
}

/* The robot's enabled links as map-frame triangles, at their poses now. */
static int robot_mesh(const self_filter_scene *s, mesh_out *mesh) {
    uint32_t count = 0, l;
    uint32_t *groups;
    int status;
    if (failed(opx_linkset_get_link_count(s->robot, &count), "opx_linkset_get_link_count")) return -1;
    groups = malloc((count + 1) * sizeof *groups);
    if (groups == NULL) return failed(OPX_ERROR_OUT_OF_MEMORY, "drawing the robot");
    for (l = 0; l < count; ++l) {
        const char *name = "";
        opx_linkset_get_link_name(s->robot, l, &name);
        groups[l] = s->is_robot_link(name) ? 0 : UINT32_MAX;
    }
    mesh_init(mesh);
    mesh_add_group(mesh, "robot", 0, 0, 0);
    status = linkset_to_mesh(s->robot, mesh, groups);
    free(groups);
    return status == 0 ? 0 : failed(OPX_ERROR_OUT_OF_MEMORY, "drawing the robot");
}

/* The frame with the robot in it: *out (malloc'd) is the composite;
 * *seen the pixels whose ray meets the robot, *replaced those where the
 * robot is nearer than the scene (or the scene has no return). */
static int composite_frame(const self_filter_scene *s, const mesh_out *mesh, float **out, size_t *seen, size_t *replaced) {
    const size_t pixels = (size_t)s->camera.width * s->camera.height;
    double *depth = malloc(pixels * sizeof *depth);
    size_t i;
    *out = malloc(pixels * 3 * sizeof **out);
    if (depth == NULL || *out == NULL || depth_render(mesh, &s->camera, depth) != 0) {
        free(depth);
        return failed(OPX_ERROR_OUT_OF_MEMORY, "rendering the robot");
    }
    memcpy(*out, s->points, pixels * 3 * sizeof **out);
    for (*seen = 0, i = 0; i < pixels; ++i) *seen += isfinite(depth[i]) != 0;
    *replaced = depth_composite(*out, depth, &s->camera);
    free(depth);
    return 0;
}

static int collide(const self_filter_scene *s, filtered_map *m) {
    double *centers = NULL, *sizes = NULL;
    size_t count = 0, i, j;
    if (demo_colliding_cells(m->map, s->robot, &centers, &sizes, &count) != 0) return -1;
    m->collides = count > 0;
    m->cells_hit = 0; /* a cell touched by several shapes counts once */
    for (i = 0; i < count; ++i) {
        for (j = 0; j < i; ++j)
            if (memcmp(&centers[3 * i], &centers[3 * j], 3 * sizeof *centers) == 0) break;
        m->cells_hit += j == i;
    }
    free(centers);
    free(sizes);
    return 0;
}

static int ingest(const self_filter_scene *s, const float *xyz, int filter, filtered_map *m) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    double start;
    m->report = (opx_insert_report)OPX_INSERT_REPORT_INIT;
    m->stats = (opx_octree_stats)OPX_OCTREE_STATS_INIT;
    options.resolution = s->resolution;
    insert.sensor_pose = s->camera.pose;
    if (filter) {
        insert.robot = s->robot;
        insert.robot_padding = s->robot_padding;
        insert.clear_robot_volume = 1;
    }
    if (failed(opx_octree_create(&options, &m->map), "opx_octree_create")) return -1;
    start = demo_now_us();
    if (failed(opx_octree_insert_points(m->map, xyz, (size_t)s->camera.width * s->camera.height, 0, OPX_SCALAR_FLOAT32,
                                        &insert, &m->report),
               "opx_octree_insert_points"))
        return -1;
    m->ms = (demo_now_us() - start) * 1e-3;
    if (failed(opx_octree_get_stats(m->map, &m->stats), "opx_octree_get_stats")) return -1;
    return collide(s, m);
}

static void panel(const self_filter_scene *s, const filtered_map *m, const mesh_out *mesh, const char *title,
                  picture_input *p) {
    memset(p, 0, sizeof *p);
    p->map = m->map;
    p->view = s->view;
    p->view.title = title;
    memcpy(p->sensor, s->camera.pose.position, sizeof p->sensor);
    memcpy(p->fov_edges, s->fov_edges, sizeof p->fov_edges);
    p->fov_edge_count = 2;
    p->arms[0] = mesh;
    p->arm_labels[0] = s->robot_label;
    p->arm_count = 1;
    p->arms_outline_only = 1;
}

static int draw(const self_filter_scene *s, const filtered_map maps[2], const mesh_out *mesh, char *path,
                size_t path_size) {
    static char title[160];
    picture_input left, right;
    snprintf(title, sizeof title, "SELF-FILTERING AT INGEST: THE ARM IN ITS OWN CAMERA'S FRAME, %g CM MAPS, SLICE "
             "THROUGH THE ARM", s->resolution * 100.0);
    panel(s, &maps[0], mesh, "WITHOUT SELF-FILTER", &left);
    panel(s, &maps[1], mesh, "WITH SELF-FILTER", &right);
    snprintf(path, path_size, "%s/%s", s->out_dir, s->picture_name);
    return demo_picture_write_pair(&left, &right, title, path);
}

static void report(const self_filter_scene *s, const filtered_map maps[2], size_t seen, size_t replaced) {
    const opx_insert_report *r = &maps[1].report;
    printf("\nself-filter      %s, rendered into the frame (exact ray casting per pixel): %zu pixels see the arm, "
           "%zu take it\n",
           s->pose_label, seen, replaced);
    printf("  without        %g cm map, %llu occupied leaves (%.0f ms); the arm %s", s->resolution * 100.0,
           (unsigned long long)maps[0].stats.leaves_occupied, maps[0].ms,
           maps[0].collides ? "collides with its own image" : "is collision-free");
    if (maps[0].collides) printf(" (%zu cells)", maps[0].cells_hit);
    printf("\n");
    printf("  with           robot_padding %g m, clear_robot_volume: %llu points on robot, %llu shadowed, %llu cells "
           "cleared;\n",
           s->robot_padding, (unsigned long long)r->points_on_robot, (unsigned long long)r->points_shadowed,
           (unsigned long long)r->cells_cleared);
    printf("                 %llu occupied leaves (%.0f ms); the arm %s", (unsigned long long)maps[1].stats.leaves_occupied,
           maps[1].ms, maps[1].collides ? "collides" : "is collision-free");
    if (maps[1].collides) printf(" (%zu cells)", maps[1].cells_hit);
    printf("\n");
}

int demo_self_filter_run(const self_filter_scene *s) {
    filtered_map maps[2];
    mesh_out mesh;
    float *xyz = NULL;
    size_t seen = 0, replaced = 0;
    char path[4096];
    int status;
    memset(maps, 0, sizeof maps);
    mesh_init(&mesh);
    status = failed(opx_linkset_set_named_joint_positions(s->robot, s->joint_names, s->positions, s->joint_count,
                                                          &s->base_pose),
                    "opx_linkset_set_named_joint_positions");
    if (status == 0) status = robot_mesh(s, &mesh);
    if (status == 0) status = composite_frame(s, &mesh, &xyz, &seen, &replaced);
    if (status == 0) status = ingest(s, xyz, 0, &maps[0]);
    if (status == 0) status = ingest(s, xyz, 1, &maps[1]);
    if (status == 0) {
        report(s, maps, seen, replaced);
        status = draw(s, maps, &mesh, path, sizeof path);
        if (status != 0) fprintf(stderr, "opx-demo: the picture %s could not be written\n", path);
        else printf("picture          %s\n", path);
    }
    free(xyz);
    mesh_free(&mesh);
    opx_octree_destroy(maps[0].map);
    opx_octree_destroy(maps[1].map);
    return status;
}
