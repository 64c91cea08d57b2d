/* The demo's story: see demo_story.h. */
#include "demo_story.h"

#include "demo_queries.h"
#include "demo_world.h"
#include "shape_mesh.h"

#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PATH_COST_BOXES 64

typedef struct story_state {
    opx_octree *map;
    opx_world *world; /* the known objects; NULL without */
    char scene_path[4096];
    int step;         /* the report's step number */
    int64_t first_hit; /* the first waypoint colliding with the map or an object, -1: none */
    uint32_t link_count;
    opx_pose *poses;             /* waypoint_count x link_count */
    waypoint_result *results;
    opx_query_stats amortized;
    opx_path_result path;
    opx_cost_box boxes[PATH_COST_BOXES];
    double ingest_ms, fk_us, path_ms;
} story_state;

static int failed(opx_status status, const char *what) {
    if (status == OPX_OK) return 0;
    fprintf(stderr, "opx-demo: %s failed: %s (%s)\n", what, opx_status_name(status), opx_last_error());
    return -1;
}

static int ingest(const demo_story *s, story_state *st) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    double start;
    options.resolution = s->resolution;
    insert.sensor_pose = s->sensor_pose;
    if (failed(opx_octree_create(&options, &st->map), "opx_octree_create")) return -1;
    start = demo_now_us();
    if (failed(opx_octree_insert_points(st->map, s->points, s->point_count, 0, OPX_SCALAR_FLOAT32, &insert, &report),
               "opx_octree_insert_points"))
        return -1;
    st->ingest_ms = (demo_now_us() - start) * 1e-3;
    if (failed(opx_octree_get_stats(st->map, &stats), "opx_octree_get_stats")) return -1;
    printf("%d. sensor frame   %s\n", ++st->step, s->frame_label);
    printf("%d. ingest         ray-cast %llu points into a %g cm map in %.0f ms: %llu occupied, %llu free leaves\n",
           ++st->step, (unsigned long long)report.points_used, s->resolution * 100.0, st->ingest_ms,
           (unsigned long long)stats.leaves_occupied, (unsigned long long)stats.leaves_free);
    return 0;
}

/* The known objects: the scene written as MoveIt exports it, read back. */
static int load_known_objects(const demo_story *s, story_state *st) {
    char objects[256];
    if (s->scene_text == NULL) return 0;
    if (demo_world_load(s->out_dir, s->scene_name, s->scene_text, st->scene_path, sizeof st->scene_path,
                        &st->world) != 0)
        return -1;
    demo_world_describe(st->world, objects, sizeof objects);
    printf("%d. known objects  %s, read from a MoveIt scene (.scene text); checked beside the map\n", ++st->step,
           objects);
    return 0;
}

/* Every link's pose at every waypoint, by FK on the straight joint line. */
static int plan_path(const demo_story *s, story_state *st) {
    const size_t n = s->waypoint_count;
    double q[STORY_MAX_JOINTS], start;
    size_t w, j;
    uint32_t l;
    if (failed(opx_linkset_get_link_count(s->robot, &st->link_count), "opx_linkset_get_link_count")) return -1;
    st->poses = malloc(n * st->link_count * sizeof *st->poses);
    st->results = calloc(n, sizeof *st->results);
    if (st->poses == NULL || st->results == NULL) return failed(OPX_ERROR_OUT_OF_MEMORY, "planning the path");
    start = demo_now_us();
    for (w = 0; w < n; ++w) {
        const double t = n > 1 ? (double)w / (double)(n - 1) : 0.0;
        for (j = 0; j < s->joint_count; ++j) q[j] = s->start[j] + t * (s->goal[j] - s->start[j]);
        if (failed(opx_linkset_set_named_joint_positions(s->robot, s->joint_names, q, s->joint_count, &s->base_pose),
                   "opx_linkset_set_named_joint_positions"))
            return -1;
        for (l = 0; l < st->link_count; ++l) opx_linkset_get_pose(s->robot, l, &st->poses[w * st->link_count + l]);
    }
    st->fk_us = (demo_now_us() - start) / (double)n;
    printf("%d. robot          %s\n", ++st->step, s->robot_label);
    printf("%d. path           %zu waypoints on a straight line in joint space (%zu joints); FK %.1f us a waypoint\n",
           ++st->step, n, s->joint_count, st->fk_us);
    return 0;
}

static int path_query(const demo_story *s, story_state *st) {
    opx_query *query = NULL;
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    double start;
    size_t i;
    request.compute_distance = 1;
    request.compute_cost = 1;
    request.max_cost_boxes = PATH_COST_BOXES;
    st->path = (opx_path_result)OPX_PATH_RESULT_INIT;
    if (failed(opx_query_create(NULL, &query), "opx_query_create")) return -1;
    start = demo_now_us();
    /* With the known objects: collision and distance along the path count
     * them; the cost is the map's unknown space alone. */
    if (failed(opx_query_set_world(query, st->world), "opx_query_set_world") ||
        failed(opx_query_path(query, st->map, s->robot, st->poses, s->waypoint_count, 0, 0, &request, &st->path),
               "opx_query_path")) {
        opx_query_destroy(query);
        return -1;
    }
    st->path_ms = (demo_now_us() - start) * 1e-3;
    for (i = 0; i < st->path.cost_box_count && i < PATH_COST_BOXES; ++i) {
        st->boxes[i] = (opx_cost_box)OPX_COST_BOX_INIT;
        opx_query_get_cost_box(query, i, &st->boxes[i]);
    }
    opx_query_destroy(query);
    return 0;
}

static int compare_doubles(const void *a, const void *b) {
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* The median of one timing over the waypoints (field offset in the result). */
static double median_us(const story_state *st, size_t n, size_t offset, int engine) {
    double *v = malloc(n * sizeof *v), m;
    size_t w;
    if (v == NULL) return NAN;
    for (w = 0; w < n; ++w) v[w] = ((const double *)((const char *)&st->results[w] + offset))[engine];
    qsort(v, n, sizeof *v, compare_doubles);
    m = v[n / 2];
    free(v);
    return m;
}

/* What waypoint w touches: "no", "map", the known objects' name, "both". */
static const char *hit_label(const demo_story *s, const waypoint_result *r) {
    if (!r->collided[0]) return "no";
    if (r->hits_map && r->hits_objects) return "both";
    return r->hits_objects ? s->known_name : "map";
}

/* What is nearest: "map" or the object's name. */
static const char *nearest_label(const story_state *st, const waypoint_result *r) {
    const char *name = "?";
    if (r->nearest_object[0] < 0) return "map";
    opx_world_get_object_name(st->world, (uint32_t)r->nearest_object[0], &name);
    return name;
}

static void print_table(const demo_story *s, story_state *st) {
    const size_t n = s->waypoint_count, step = n > 12 ? n / 10 : 1;
    size_t w;
    printf("%d. each waypoint  collision, distance%s and unknown-space cost, both engines (times in us)\n", ++st->step,
           st->world != NULL ? " (the map and the known objects)" : "");
    printf("   %4s  %-8s  %10s %-8s %10s   %-24s  %-24s\n", "wp", "collides", "distance m", "nearest", "cost m^3",
           "direct coll/dist/cost", "amortized coll/dist/cost");
    for (w = 0; w < n; ++w) {
        const waypoint_result *r = &st->results[w];
        const int first_hit = (int64_t)w == st->first_hit;
        if (w % step != 0 && w + 1 != n && !first_hit) continue;
        printf("   %4zu  %-8s  %10.4f %-8s %10.5f   %6.0f /%6.0f /%6.0f    %6.0f /%6.0f /%6.0f%s\n", w, hit_label(s, r),
               r->distance[0], nearest_label(st, r), r->cost[0], r->collide_us[0], r->distance_us[0], r->cost_us[0],
               r->collide_us[1], r->distance_us[1], r->cost_us[1], first_hit ? "   <- first collision" : "");
    }
}

static void print_collisions(const demo_story *s, story_state *st) {
    const size_t n = s->waypoint_count;
    size_t w, colliding = 0, on_map = 0, on_objects = 0;
    for (w = 0; w < n; ++w) {
        colliding += st->results[w].collided[0] != 0;
        on_map += st->results[w].hits_map != 0;
        on_objects += st->results[w].hits_objects != 0;
    }
    printf("%d. path query     %s; minimum distance %.4f m at waypoint %lld; swept unknown-space cost %.4f m^3 in "
           "%llu cells (%.1f ms)\n",
           ++st->step, st->path.collided ? "collides" : "collision-free", st->path.min_distance,
           (long long)st->path.min_distance_waypoint, st->path.total_cost, (unsigned long long)st->path.cost_boxes_found,
           st->path_ms);
    if (st->path.first_colliding_waypoint != st->first_hit)
        printf("                  DISAGREES with the waypoints' first collision, %lld\n", (long long)st->first_hit);
    if (st->world != NULL && st->first_hit >= 0)
        printf("                  first collision at waypoint %lld; %zu of %zu waypoints collide (%zu with the map, "
               "%zu with the known %s)\n",
               (long long)st->first_hit, colliding, n, on_map, on_objects, s->known_name);
    else if (st->first_hit >= 0)
        printf("                  first collision at waypoint %lld; %zu of %zu waypoints collide\n",
               (long long)st->first_hit, colliding, n);
}

static void print_summary(const demo_story *s, story_state *st) {
    const size_t n = s->waypoint_count;
    size_t w, disagree = 0;
    double worst = 0.0;
    for (w = 0; w < n; ++w) {
        const waypoint_result *r = &st->results[w];
        const double diff = fabs(r->distance[0] - r->distance[1]);
        disagree += r->collided[0] != r->collided[1] || diff > 1e-9 || fabs(r->cost[0] - r->cost[1]) > 1e-12 ||
                    r->nearest_object[0] != r->nearest_object[1];
        if (diff > worst) worst = diff;
    }
    print_collisions(s, st);
    printf("%d. engines        %s on all %zu waypoints (largest distance difference %.1e m)\n", ++st->step,
           disagree ? "DISAGREE" : "agree (collision, distance, cost)", n, worst);
    printf("%d. timings        median a waypoint: direct %.0f us collision, %.0f us distance, %.0f us cost;\n",
           ++st->step, median_us(st, n, offsetof(waypoint_result, collide_us), 0),
           median_us(st, n, offsetof(waypoint_result, distance_us), 0), median_us(st, n, offsetof(waypoint_result, cost_us), 0));
    printf("                  amortized %.0f us collision, %.0f us distance, %.0f us cost (cost queries need the octree: "
           "direct inside),\n",
           median_us(st, n, offsetof(waypoint_result, collide_us), 1), median_us(st, n, offsetof(waypoint_result, distance_us), 1),
           median_us(st, n, offsetof(waypoint_result, cost_us), 1));
    printf("                  after one bind of the frame (%.1f ms extract + %.1f ms build, %llu boxes)\n",
           st->amortized.extract_ms, st->amortized.build_ms, (unsigned long long)st->amortized.boxes);
}

/* A few waypoints to draw: the ends, the first collision, and between. */
static size_t pick_waypoints(const demo_story *s, const story_state *st, size_t *out) {
    const size_t n = s->waypoint_count;
    const int64_t hit = st->first_hit;
    size_t candidates[5] = {0, n / 3, hit >= 0 ? (size_t)hit : n / 2, 2 * n / 3, n - 1}, count = 0, i, j;
    for (i = 0; i < 5; ++i) {
        int seen = 0;
        for (j = 0; j < count; ++j) seen |= out[j] == candidates[i];
        if (!seen && candidates[i] < n) out[count++] = candidates[i];
    }
    for (i = 1; i < count; ++i) /* ascending */
        for (j = i; j > 0 && out[j - 1] > out[j]; --j) {
            const size_t t = out[j];
            out[j] = out[j - 1];
            out[j - 1] = t;
        }
    return count;
}

/* groups[l]: 0 to draw link l in this mesh, UINT32_MAX to leave it out. */
static void link_groups(const demo_story *s, uint32_t link_count, int body, uint32_t *groups) {
    uint32_t l;
    for (l = 0; l < link_count; ++l) {
        const char *name = "";
        int is_body;
        opx_linkset_get_link_name(s->robot, l, &name);
        is_body = s->is_body_link != NULL && s->is_body_link(name);
        groups[l] = is_body == body ? 0 : UINT32_MAX;
    }
}

static void robot_mesh(const demo_story *s, const story_state *st, size_t waypoint, const uint32_t *groups, mesh_out *m) {
    mesh_init(m);
    mesh_add_group(m, "robot", 0, 0, 0);
    opx_linkset_set_poses(s->robot, st->poses + waypoint * st->link_count, st->link_count, 0);
    linkset_to_mesh(s->robot, m, groups);
}

/* The tool link's position at every waypoint and which waypoints collide;
 * -1 without a tool link, or out of memory (the picture goes without). */
static int tool_path(const demo_story *s, const story_state *st, double **out, unsigned char **hits) {
    const size_t n = s->waypoint_count;
    uint32_t tool;
    size_t w;
    if (s->tool_link == NULL || opx_linkset_find_link(s->robot, s->tool_link, &tool) != OPX_OK) return -1;
    *out = malloc(3 * n * sizeof **out);
    *hits = malloc(n);
    if (*out == NULL || *hits == NULL) return -1;
    for (w = 0; w < n; ++w) {
        memcpy(&(*out)[3 * w], st->poses[w * st->link_count + tool].position, 3 * sizeof **out);
        (*hits)[w] = st->results[w].collided[0] != 0;
    }
    return 0;
}

/* The known objects and the points where the robot touches them, for the
 * picture (none without a world). */
static void known_for_picture(const demo_story *s, const story_state *st, mesh_out *known, double **contacts,
                              size_t *count) {
    size_t w;
    mesh_init(known);
    if (st->world == NULL) return;
    demo_world_mesh(st->world, known);
    for (w = 0; w < s->waypoint_count; ++w) {
        if (!st->results[w].hits_objects) continue;
        opx_linkset_set_poses(s->robot, st->poses + w * st->link_count, st->link_count, 0);
        demo_world_contacts(st->world, s->robot, contacts, count);
    }
}

static int draw(demo_story *s, story_state *st, char *path, size_t path_size) {
    static mesh_out arms[PICTURE_MAX_ARMS], body, known;
    static char labels[PICTURE_MAX_ARMS][32];
    uint32_t *groups = malloc((st->link_count + 1) * sizeof *groups);
    size_t picked[5], count = pick_waypoints(s, st, picked), i, w;
    double *centers = NULL, *sizes = NULL, *tool = NULL, *contacts = NULL;
    unsigned char *tool_hits = NULL;
    size_t cells = 0, contact_count = 0;
    int status;
    picture_input *p = &s->picture;
    if (groups == NULL) return -1;
    for (w = 0; w < s->waypoint_count; ++w) {
        if (!st->results[w].collided[0]) continue;
        opx_linkset_set_poses(s->robot, st->poses + w * st->link_count, st->link_count, 0);
        demo_colliding_cells(st->map, s->robot, &centers, &sizes, &cells);
    }
    known_for_picture(s, st, &known, &contacts, &contact_count);
    p->known = st->world != NULL ? &known : NULL;
    p->object_contacts = contacts;
    p->object_contact_count = contact_count;
    link_groups(s, st->link_count, 1, groups);
    robot_mesh(s, st, 0, groups, &body);
    p->body = body.face_count > 0 ? &body : NULL;
    link_groups(s, st->link_count, 0, groups);
    for (i = 0; i < count && i < PICTURE_MAX_ARMS; ++i) {
        robot_mesh(s, st, picked[i], groups, &arms[i]);
        snprintf(labels[i], sizeof labels[i], "WAYPOINT %zu", picked[i]);
        p->arms[i] = &arms[i];
        p->arm_labels[i] = labels[i];
        p->arm_collides[i] = st->results[picked[i]].collided[0];
        p->arm_waypoints[i] = picked[i];
    }
    p->arm_count = (int)i;
    if (tool_path(s, st, &tool, &tool_hits) == 0) {
        p->tool_path = tool;
        p->tool_collides = tool_hits;
        p->tool_path_count = s->waypoint_count;
    }
    p->map = st->map;
    p->colliding_centers = centers;
    p->colliding_sizes = sizes;
    p->colliding_count = cells;
    p->cost_boxes = st->boxes;
    p->cost_box_count = st->path.cost_box_count < PATH_COST_BOXES ? (size_t)st->path.cost_box_count : PATH_COST_BOXES;
    p->total_cost = st->path.total_cost;
    snprintf(path, path_size, "%s/%s", s->out_dir, s->picture_name);
    status = demo_picture_write(p, path);
    for (i = 0; i < (size_t)p->arm_count; ++i) mesh_free(&arms[i]);
    mesh_free(&body);
    mesh_free(&known);
    free(contacts);
    free(groups);
    free(centers);
    free(sizes);
    free(tool);
    free(tool_hits);
    p->tool_path = NULL;
    p->tool_collides = NULL;
    p->tool_path_count = 0;
    p->known = NULL;
    p->object_contacts = NULL;
    p->object_contact_count = 0;
    return status;
}

static int64_t first_collision(const demo_story *s, const story_state *st) {
    size_t w;
    for (w = 0; w < s->waypoint_count; ++w)
        if (st->results[w].collided[0]) return (int64_t)w;
    return -1;
}

int demo_story_run(demo_story *s) {
    story_state st;
    char picture[4096], map[4096];
    int status;
    memset(&st, 0, sizeof st);
    st.amortized = (opx_query_stats)OPX_QUERY_STATS_INIT;
    st.first_hit = -1;
    status = ingest(s, &st) == 0 && load_known_objects(s, &st) == 0 && plan_path(s, &st) == 0 ? 0 : -1;
    if (status == 0)
        status = demo_queries_run(st.map, st.world, s->robot, st.poses, s->waypoint_count, st.link_count, st.results,
                                  &st.amortized);
    if (status == 0) status = path_query(s, &st);
    if (status == 0) st.first_hit = first_collision(s, &st);
    if (status == 0) {
        print_table(s, &st);
        print_summary(s, &st);
        status = draw(s, &st, picture, sizeof picture);
        if (status != 0) fprintf(stderr, "opx-demo: the picture %s could not be written\n", picture);
    }
    if (status == 0) {
        snprintf(map, sizeof map, "%s/%s", s->out_dir, s->map_name);
        status = failed(opx_octree_save_file(st.map, map, OPX_FORMAT_BT), "opx_octree_save_file");
    }
    if (status == 0) printf("\npicture  %s\nmap      %s (octovis, or: octoprox info / export)\n", picture, map);
    if (status == 0 && st.world != NULL)
        printf("scene    %s (MoveIt .scene text; octoprox check MAP --scene FILE --urdf ROBOT)\n", st.scene_path);
    free(st.poses);
    free(st.results);
    opx_world_destroy(st.world);
    opx_octree_destroy(st.map);
    return status;
}
