/* Fuzzed query requests and checks of their results: see fuzz_api_requests.h. */
#include "fuzz_api_requests.h"

static int32_t take_policy(fuzz_input *in) {
    const uint8_t kind = take_u8(in);
    return kind < 120 ? OPX_UNKNOWN_FREE : kind < 240 ? OPX_UNKNOWN_OCCUPIED : (int32_t)take_u32(in);
}

/* 0 (the octree's threshold) most of the time. */
static double take_threshold(fuzz_input *in) { return take_u8(in) < 160 ? 0.0 : take_fraction(in); }

static int32_t take_flag(fuzz_input *in) {
    const uint8_t kind = take_u8(in);
    return kind < 248 ? kind & 1 : (int32_t)take_u32(in);
}

static uint32_t take_limit(fuzz_input *in) {
    static const uint32_t limits[] = {0, 1, 2, 4, 16, UINT32_MAX};
    return take_u8(in) < 240 ? limits[take_below(in, 6)] : take_u32(in);
}

/* A region: mostly the default (none), else small boxes or any doubles. */
static void take_region(fuzz_input *in, double min[3], double max[3]) {
    const uint8_t kind = take_u8(in);
    if (kind < 128) return;
    for (int axis = 0; axis < 3; ++axis) {
        min[axis] = kind < 224 ? (double)(int8_t)take_u8(in) / 20.0 : take_double(in);
        max[axis] = kind < 224 ? min[axis] + take_u8(in) / 20.0 : take_double(in);
    }
}

void take_collision_request(fuzz_input *in, opx_collision_request *request) {
    request->struct_size = take_struct_size(in, sizeof *request);
    request->unknown_policy = take_policy(in);
    request->occupancy_threshold = take_threshold(in);
    request->max_contacts = take_limit(in);
    request->compute_cost = take_flag(in);
    request->max_cost_boxes = take_limit(in);
    request->unknown_probability = take_fraction(in);
    take_region(in, request->region_min, request->region_max);
    request->compute_penetration = take_flag(in);
}

static double take_error_bound(fuzz_input *in) {
    const uint8_t kind = take_u8(in);
    return kind < 192 ? 0.0 : kind < 240 ? (kind - 192) / 50.0 : take_double(in);
}

void take_sphere_request(fuzz_input *in, opx_sphere_request *request) {
    request->struct_size = take_struct_size(in, sizeof *request);
    request->unknown_policy = take_policy(in);
    request->occupancy_threshold = take_threshold(in);
    const uint8_t geometry = take_u8(in);
    request->obstacle_geometry =
        geometry < 160 ? OPX_OBSTACLE_CELLS : geometry < 240 ? OPX_OBSTACLE_POINT_EXTENTS : geometry;
}

int yes_no_collides(opx_query *query, const opx_octree *tree, const opx_linkset *links, int32_t unknown_policy,
                    double occupancy_threshold, int32_t obstacle_geometry) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = 0;
    request.unknown_policy = unknown_policy;
    request.occupancy_threshold = occupancy_threshold;
    request.obstacle_geometry = obstacle_geometry;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    if (opx_query_collide(query, tree, links, &request, &result) != OPX_OK) return -1;
    return result.collided;
}

void take_batch_request(fuzz_input *in, opx_batch_request *request) {
    request->struct_size = take_struct_size(in, sizeof *request);
    request->unknown_policy = take_policy(in);
    request->occupancy_threshold = take_threshold(in);
    const uint8_t threads = take_u8(in);
    request->max_threads = threads < 240 ? 1 + threads % 3 : take_u32(in);
    const uint8_t geometry = take_u8(in);
    request->obstacle_geometry =
        geometry < 160 ? OPX_OBSTACLE_CELLS : geometry < 240 ? OPX_OBSTACLE_POINT_EXTENTS : geometry;
}

void take_distance_request(fuzz_input *in, opx_distance_request *request) {
    request->struct_size = take_struct_size(in, sizeof *request);
    request->unknown_policy = take_policy(in);
    request->occupancy_threshold = take_threshold(in);
    request->abs_err = take_error_bound(in);
    request->rel_err = take_error_bound(in);
    const uint8_t cutoff = take_u8(in);
    request->cutoff = cutoff < 160 ? 0.0 : cutoff < 240 ? (cutoff - 160) / 20.0 : take_double(in);
    request->per_link = take_flag(in);
    request->signed_distance = take_flag(in);
}

void take_path_request(fuzz_input *in, opx_path_request *request) {
    request->struct_size = take_struct_size(in, sizeof *request);
    request->unknown_policy = take_policy(in);
    request->occupancy_threshold = take_threshold(in);
    request->compute_distance = take_flag(in);
    request->compute_cost = take_flag(in);
    request->max_cost_boxes = take_limit(in);
    request->unknown_probability = take_fraction(in);
    take_region(in, request->region_min, request->region_max);
}

/* What the library reads: the caller's first struct_size bytes over the
 * defaults. */
static void effective(void *merged, const void *request, size_t size) {
    if (request == NULL) return;
    uint32_t struct_size;
    memcpy(&struct_size, request, sizeof struct_size);
    memcpy(merged, request, struct_size < size ? struct_size : size);
}

void check_collision_result(const opx_collision_request *caller, const opx_collision_result *result) {
    opx_collision_request merged = OPX_COLLISION_REQUEST_INIT;
    effective(&merged, caller, sizeof merged);
    const opx_collision_request *request = &merged;
    FUZZ_REQUIRE(result->collided == 0 || result->collided == 1);
    FUZZ_REQUIRE(result->truncated == 0 || result->truncated == 1);
    FUZZ_REQUIRE(result->contact_count == 0 || result->collided);
    if (request->max_contacts > 0) FUZZ_REQUIRE(result->contact_count <= request->max_contacts);
    if (request->max_contacts > 0 && result->collided) FUZZ_REQUIRE(result->contact_count > 0);
    FUZZ_REQUIRE(result->cost_box_count <= result->cost_boxes_found);
    if (request->compute_cost) FUZZ_REQUIRE(result->cost_box_count <= request->max_cost_boxes);
    else FUZZ_REQUIRE(result->cost_box_count == 0);
}

void check_distance_result(const opx_distance_request *caller, const opx_distance_result *result) {
    opx_distance_request merged = OPX_DISTANCE_REQUEST_INIT;
    effective(&merged, caller, sizeof merged);
    const opx_distance_request *request = &merged;
    FUZZ_REQUIRE(result->found == 0 || result->found == 1);
    FUZZ_REQUIRE(result->collided == 0 || result->collided == 1);
    if (!result->found) {
        const double cutoff = request->cutoff > 0.0 ? request->cutoff : INFINITY;
        FUZZ_REQUIRE(result->distance == cutoff);
        return;
    }
    FUZZ_REQUIRE(!isnan(result->distance));
    FUZZ_REQUIRE(result->collided == (result->distance <= 1e-9));
    if (!request->signed_distance) FUZZ_REQUIRE(result->distance >= 0.0);
}

static int same_distance(double a, double b) {
    if (a == b) return 1;
    return fabs(a - b) <= 1e-9 * fmax(1.0, fmax(fabs(a), fabs(b)));
}

void check_same_distance(const opx_distance_result *a, const opx_distance_result *b) {
    FUZZ_REQUIRE(a->found == b->found);
    FUZZ_REQUIRE(same_distance(a->distance, b->distance));
}
