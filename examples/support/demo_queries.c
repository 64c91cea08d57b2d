/* The demo's per-waypoint queries: see demo_queries.h. */
#define _POSIX_C_SOURCE 200809L

#include "demo_queries.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static const int32_t kEngines[DEMO_ENGINES] = {OPX_ENGINE_DIRECT, OPX_ENGINE_AMORTIZED};

double demo_now_us(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e6 + (double)ts.tv_nsec * 1e-3;
}

static int failed(opx_status status, const char *what) {
    if (status == OPX_OK) return 0;
    fprintf(stderr, "opx-demo: %s failed: %s (%s)\n", what, opx_status_name(status), opx_last_error());
    return -1;
}

/* The three queries of one waypoint with one engine. */
static int query_waypoint(opx_query *query, const opx_octree *map, const opx_linkset *robot, int e,
                          waypoint_result *r) {
    opx_collision_request collide = OPX_COLLISION_REQUEST_INIT, cost = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT, priced = OPX_COLLISION_RESULT_INIT;
    opx_distance_result near = OPX_DISTANCE_RESULT_INIT;
    double t0, t1, t2, t3;
    collide.max_contacts = 0; /* yes or no */
    cost.compute_cost = 1;
    t0 = demo_now_us();
    if (failed(opx_query_collide(query, map, robot, &collide, &hit), "opx_query_collide")) return -1;
    t1 = demo_now_us();
    if (failed(opx_query_distance(query, map, robot, NULL, &near), "opx_query_distance")) return -1;
    t2 = demo_now_us();
    if (failed(opx_query_collide(query, map, robot, &cost, &priced), "opx_query_collide (cost)")) return -1;
    t3 = demo_now_us();
    r->collided[e] = hit.collided;
    r->distance[e] = near.distance;
    r->nearest_object[e] = near.object;
    r->cost[e] = priced.total_cost;
    r->collide_us[e] = t1 - t0;
    r->distance_us[e] = t2 - t1;
    r->cost_us[e] = t3 - t2;
    return 0;
}

/* Yes or no, on a context with `world` set (NULL: none) and `map` (may be
 * NULL with a world). */
static int collides(opx_query *query, const opx_octree *map, const opx_world *world, const opx_linkset *robot,
                    int *out) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    request.max_contacts = 0;
    if (failed(opx_query_set_world(query, world), "opx_query_set_world") ||
        failed(opx_query_collide(query, map, robot, &request, &hit), "opx_query_collide"))
        return -1;
    *out = hit.collided;
    return 0;
}

/* Which of the map and the known objects each waypoint touches. */
static int split_hits(const opx_octree *map, const opx_world *world, opx_linkset *robot, const opx_pose *poses,
                      size_t waypoint_count, size_t link_count, waypoint_result *out) {
    opx_query *query = NULL;
    size_t w;
    int status = 0;
    if (failed(opx_query_create(NULL, &query), "opx_query_create")) return -1;
    for (w = 0; w < waypoint_count && status == 0; ++w) {
        status = failed(opx_linkset_set_poses(robot, poses + w * link_count, link_count, 0), "opx_linkset_set_poses");
        if (status == 0) status = collides(query, map, NULL, robot, &out[w].hits_map);
        out[w].hits_objects = 0;
        if (status == 0 && world != NULL) status = collides(query, NULL, world, robot, &out[w].hits_objects);
    }
    opx_query_set_world(query, NULL);
    opx_query_destroy(query);
    return status;
}

int demo_queries_run(const opx_octree *map, const opx_world *world, opx_linkset *robot, const opx_pose *poses,
                     size_t waypoint_count, size_t link_count, waypoint_result *out, opx_query_stats *stats) {
    int e;
    size_t w;
    for (e = 0; e < DEMO_ENGINES; ++e) {
        opx_query_options options = OPX_QUERY_OPTIONS_INIT;
        opx_query *query = NULL;
        int status = 0;
        options.engine = kEngines[e];
        if (failed(opx_query_create(&options, &query), "opx_query_create")) return -1;
        status = failed(opx_query_set_world(query, world), "opx_query_set_world");
        for (w = 0; w < waypoint_count && status == 0; ++w) {
            status = failed(opx_linkset_set_poses(robot, poses + w * link_count, link_count, 0), "opx_linkset_set_poses");
            if (status == 0) status = query_waypoint(query, map, robot, e, &out[w]);
        }
        if (status == 0 && kEngines[e] == OPX_ENGINE_AMORTIZED)
            status = failed(opx_query_get_stats(query, stats), "opx_query_get_stats");
        opx_query_set_world(query, NULL);
        opx_query_destroy(query);
        if (status != 0) return -1;
    }
    return split_hits(map, world, robot, poses, waypoint_count, link_count, out);
}

int demo_colliding_cells(const opx_octree *map, const opx_linkset *robot, double **centers, double **sizes,
                         size_t *count) {
    opx_query *query = NULL;
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    opx_collision_result hit = OPX_COLLISION_RESULT_INIT;
    uint64_t i;
    request.max_contacts = UINT32_MAX;
    if (failed(opx_query_create(NULL, &query), "opx_query_create")) return -1;
    if (failed(opx_query_collide(query, map, robot, &request, &hit), "opx_query_collide")) {
        opx_query_destroy(query);
        return -1;
    }
    for (i = 0; i < hit.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        double *c = realloc(*centers, (*count + 1) * 3 * sizeof(double)), *s;
        if (c != NULL) *centers = c;
        s = realloc(*sizes, (*count + 1) * sizeof(double));
        if (s != NULL) *sizes = s;
        if (c == NULL || s == NULL || opx_query_get_contact(query, (size_t)i, &contact) != OPX_OK) break;
        c[3 * *count] = contact.cell_center[0];
        c[3 * *count + 1] = contact.cell_center[1];
        c[3 * *count + 2] = contact.cell_center[2];
        s[*count] = contact.cell_size;
        ++*count;
    }
    opx_query_destroy(query);
    return 0;
}
