/* The sphere operation of the call-sequence fuzzer: spheres against a map
 * (opx_query_collide_spheres), each checked against the answer of
 * opx_query_collide for a link set holding that sphere alone.  Between
 * calls the map may be changed or cleared, so the map's obstacle grid is
 * built, kept and rebuilt along the way.  The signed distances of the
 * same kind of rows (opx_query_distance_spheres) agree with the sphere
 * checks away from the touch limit.  See fuzz_api.h. */
#include "fuzz_api.h"
#include "fuzz_api_requests.h"

#include <math.h>

enum { MAX_SPHERES = 8 };

/* Mostly 2 to 66 cm (a record's end reads zeros: 2 cm); a link set
 * refuses a radius of 0, which the call under test takes. */
static double take_radius(fuzz_input *in) {
    const uint8_t kind = take_u8(in);
    return kind < 200 ? 0.02 + take_u8(in) / 400.0 : take_double(in);
}

/* A row: mostly near an occupied leaf (a record's end reads zeros: at
 * its centre) or touching one of its faces exactly, else anywhere. */
static void take_row(fuzz_input *in, const occupied_targets *targets, double row[4]) {
    row[3] = take_radius(in);
    const uint8_t kind = take_u8(in);
    if (targets->count == 0 || kind >= 224) {
        for (int axis = 0; axis < 3; ++axis) row[axis] = take_double(in);
        return;
    }
    const opx_leaf *leaf = &targets->leaves[take_below(in, targets->count)];
    for (int axis = 0; axis < 3; ++axis) row[axis] = leaf->center[axis] + (double)(int8_t)take_u8(in) / 200.0;
    if (kind >= 64 && kind < 128) { /* beyond a face, at exactly the radius */
        const int axis = kind % 3;
        row[axis] = leaf->center[axis] + (kind & 4 ? 1 : -1) * (0.5 * leaf->size + row[3]);
    }
}

/* Whether a link set of one sphere (radius, centre) touches the map as
 * opx_query_collide says; -1 when a call refuses. */
/* Sphere rows (x, y, z, radius), mostly ones the calls accept: one or
 * more, packed, near the map's occupied cells; `step` is the bytes from
 * one row to the next.  The caller frees them. */
static double *take_sphere_rows(fuzz_input *in, const opx_octree *tree, size_t *count, size_t *stride,
                                size_t *step) {
    const uint8_t many = take_u8(in);
    *count = many < 160 ? 1 + many % 3 : many < 240 ? 1 + take_below(in, MAX_SPHERES) : 0;
    *stride = take_u8(in) < 192 ? 0 : take_stride(in, 4 * sizeof(double));
    *step = *stride == 0 ? 4 * sizeof(double) : *stride;
    occupied_targets targets;
    find_occupied_targets(tree, &targets);
    double *rows = calloc(array_bytes(*count, *stride, 4 * sizeof(double)) / sizeof(double) + 4, sizeof(double));
    FUZZ_REQUIRE(rows != NULL);
    for (size_t i = 0; i < *count && *step >= 4 * sizeof(double); ++i) {
        double row[4];
        take_row(in, &targets, row);
        memcpy((char *)rows + i * *step, row, sizeof row);
    }
    return rows;
}

static int one_sphere_collides(opx_query *query, const opx_octree *tree, const double row[4],
                               const opx_sphere_request *request) {
    opx_linkset *links = NULL;
    uint32_t link = 0;
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_SPHERE;
    shape.radius = row[3];
    opx_pose pose = OPX_POSE_IDENTITY;
    for (int axis = 0; axis < 3; ++axis) pose.position[axis] = row[axis];
    int collided = -1;
    if (opx_linkset_create(&links) == OPX_OK && opx_linkset_add_link(links, "sphere", &link) == OPX_OK &&
        opx_linkset_add_shape(links, link, &shape, NULL) == OPX_OK &&
        opx_linkset_set_poses(links, &pose, 1, 0) == OPX_OK)
        collided = yes_no_collides(query, tree, links, request->unknown_policy, request->occupancy_threshold,
                                   request->obstacle_geometry);
    opx_linkset_destroy(links);
    return collided;
}

void op_query_spheres(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query *query = take_query(api);
    const opx_octree *tree = take_tree(api);
    opx_sphere_request request = OPX_SPHERE_REQUEST_INIT;
    take_sphere_request(in, &request);
    const int with_request = take_u8(in) < 240;
    size_t count, stride, step;
    double *rows = take_sphere_rows(in, tree, &count, &stride, &step);
    uint8_t collided[MAX_SPHERES + 1];
    const size_t capacity = take_u8(in) < 240 ? count : take_below(in, MAX_SPHERES + 1);
    const opx_status status = FUZZ_CALL(opx_query_collide_spheres, query, tree, take_u8(in) < 250 ? rows : NULL,
                                        count, stride, with_request ? &request : NULL, collided, capacity);
    if (status == OPX_OK && tree != NULL && with_request && request.struct_size == sizeof request) {
        for (size_t i = 0; i < count; ++i) {
            double row[4];
            memcpy(row, (const char *)rows + i * step, sizeof row);
            const int expected = one_sphere_collides(api->reference[0], tree, row, &request);
            if (expected >= 0) FUZZ_REQUIRE(collided[i] == expected);
        }
    }
    free(rows);
}

/* A distance request: the sphere request's fields, then threads and a
 * max_distance (mostly 2 to 66 cm, sometimes any double). */
static void take_sphere_distance_request(fuzz_input *in, opx_sphere_distance_request *request,
                                         opx_sphere_request *as_check) {
    take_sphere_request(in, as_check);
    request->struct_size = as_check->struct_size == sizeof *as_check ? sizeof *request : as_check->struct_size;
    request->unknown_policy = as_check->unknown_policy;
    request->occupancy_threshold = as_check->occupancy_threshold;
    request->obstacle_geometry = as_check->obstacle_geometry;
    request->max_threads = take_u8(in) % 4;
    request->max_distance = take_radius(in);
}

void op_query_sphere_distance(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query *query = take_query(api);
    const opx_octree *tree = take_tree(api);
    opx_sphere_distance_request request = OPX_SPHERE_DISTANCE_REQUEST_INIT;
    opx_sphere_request as_check = OPX_SPHERE_REQUEST_INIT;
    take_sphere_distance_request(in, &request, &as_check);
    size_t count, stride, step;
    double *rows = take_sphere_rows(in, tree, &count, &stride, &step);
    double distance[MAX_SPHERES + 1], gradient[3 * (MAX_SPHERES + 1)];
    const size_t capacity = take_u8(in) < 240 ? count : take_below(in, MAX_SPHERES + 1);
    const int with_gradient = take_u8(in) < 200;
    const opx_status status =
        FUZZ_CALL(opx_query_distance_spheres, query, tree, take_u8(in) < 250 ? rows : NULL, count, stride, &request,
                  distance, with_gradient ? gradient : NULL, NULL, capacity);
    if (status != OPX_OK || tree == NULL) {
        free(rows);
        return;
    }
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    FUZZ_REQUIRE(opx_octree_get_options(tree, &options) == OPX_OK);
    const double resolution = options.resolution;
    uint8_t collided[MAX_SPHERES + 1];
    const int checked = FUZZ_CALL(opx_query_collide_spheres, api->reference[0], tree, rows, count, stride, &as_check,
                                  collided, count) == OPX_OK;
    for (size_t i = 0; i < count; ++i) {
        FUZZ_REQUIRE(distance[i] <= request.max_distance);
        if (with_gradient) {
            const double *g = gradient + 3 * i, norm = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
            FUZZ_REQUIRE(norm == 0.0 || fabs(norm - 1.0) < 1e-9);
            FUZZ_REQUIRE((norm == 0.0) == (distance[i] == request.max_distance));
        }
        /* Away from the touch limit (rounding of far centres included) both calls agree. */
        double row[4];
        memcpy(row, (const char *)rows + i * step, sizeof row);
        const double scale = fmax(fabs(row[0]), fmax(fabs(row[1]), fmax(fabs(row[2]), row[3])));
        const double margin = 1e-6 + 1e-12 * scale + 1e-7 * resolution;
        if (checked && distance[i] > margin) FUZZ_REQUIRE(collided[i] == 0);
        if (checked && distance[i] < -margin) FUZZ_REQUIRE(collided[i] == 1);
    }
    free(rows);
}
