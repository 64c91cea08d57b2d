/* The batch operation of the call-sequence fuzzer: joint vectors of a link
 * set (mostly a robot from op_robot_load, the one of spheres alone among
 * them, which the batch checks on the map's obstacle grid) against a map,
 * on 1 to 3 threads.  Each accepted answer must equal the single call's:
 * forward kinematics on a clone of the link set, then opx_query_collide
 * with the same settings.  The trajectory cost of the same rows is checked
 * for a finite answer that a second query repeats.  A record with bytes
 * left after the batch's also checks the motion from its first row to its
 * last, sampled or certified: a motion called free has free ends (the
 * single calls), and a certified "free" is never a sampled "collides".
 * See fuzz_api.h. */
#include "fuzz_api.h"
#include "fuzz_api_requests.h"

enum { MAX_ROWS = 4, MAX_JOINTS = 16 };

/* The robot's root: mostly within half a metre of one of the map's first
 * occupied leaves, in any orientation; else any pose. */
static void take_base(fuzz_input *in, const opx_octree *tree, opx_pose *base) {
    take_pose(in, base);
    occupied_targets targets;
    find_occupied_targets(tree, &targets);
    if (targets.count == 0 || take_u8(in) >= 224) return;
    const opx_leaf *leaf = &targets.leaves[take_below(in, targets.count)];
    for (int axis = 0; axis < 3; ++axis)
        base->position[axis] = leaf->center[axis] + (double)(int8_t)take_u8(in) / 256.0;
}

/* The single call's answer for one row; -1 when a call refuses. */
static int single_collides(opx_query *query, const opx_octree *tree, const opx_linkset *links, const double *row,
                           size_t joints, const opx_pose *base, const opx_batch_request *request) {
    opx_linkset *clone = NULL;
    int collided = -1;
    if (opx_linkset_clone(links, &clone) == OPX_OK &&
        opx_linkset_set_joint_positions(clone, row, joints, base) == OPX_OK)
        collided = yes_no_collides(query, tree, clone, request->unknown_policy, request->occupancy_threshold,
                                   request->obstacle_geometry);
    opx_linkset_destroy(clone);
    return collided;
}

/* The motion from row 0 to row count - 1 of `rows` (small joint values
 * only: a long motion near obstacles may take the certified check
 * many steps). */
static void check_motion_of_rows(fuzz_api *api, opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                 const double *rows, size_t count, size_t joints, const opx_pose *base) {
    fuzz_input *in = &api->in;
    const uint8_t kind = take_u8(in);
    if (kind == 0 || count == 0 || joints == 0) return; /* records without the bytes: no motion */
    for (size_t i = 0; i < count * joints; ++i)
        if (!(rows[i] > -10.0 && rows[i] < 10.0)) return;
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.check = kind < 200 ? OPX_MOTION_CERTIFIED : kind < 250 ? OPX_MOTION_SAMPLED : (int32_t)take_u32(in);
    const uint8_t tolerance = take_u8(in);
    request.tolerance = tolerance < 240 ? (tolerance + 1) / 256.0 : take_double(in);
    request.resolution = 0.05;
    request.self_collision = take_u8(in) >= 192;
    request.max_threads = 1 + take_below(in, 3);
    const uint8_t geometry = take_u8(in);
    request.obstacle_geometry = geometry < 200 ? OPX_OBSTACLE_CELLS : OPX_OBSTACLE_POINT_EXTENTS;
    const double *start = rows, *goal = rows + (count - 1) * joints;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    const opx_status status =
        FUZZ_CALL(opx_query_check_motion, query, tree, links, start, goal, joints, base, &request, &result);
    if (status != OPX_OK) return;
    FUZZ_REQUIRE(result.collided == (result.first_collision_fraction >= 0.0));
    FUZZ_REQUIRE(result.first_collision_fraction <= 1.0);
    if (result.collided || tree == NULL || request.self_collision || links == NULL) return;
    const opx_batch_request yes_no = {sizeof yes_no, OPX_UNKNOWN_FREE, 0.0, 0, 0, 0.0, 1,
                                      request.obstacle_geometry, OPX_JOINTS_BY_COUNT, 0};
    FUZZ_REQUIRE(single_collides(api->reference[0], tree, links, start, joints, base, &yes_no) != 1);
    FUZZ_REQUIRE(single_collides(api->reference[0], tree, links, goal, joints, base, &yes_no) != 1);
    if (request.check != OPX_MOTION_CERTIFIED) return;
    request.check = OPX_MOTION_SAMPLED;
    if (FUZZ_CALL(opx_query_check_motion, query, tree, links, start, goal, joints, base, &request, &result) == OPX_OK)
        FUZZ_REQUIRE(!result.collided);
}

void op_query_batch(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query *query = take_query(api);
    const opx_octree *tree = take_tree(api);
    const opx_linkset *links = take_linkset(api);
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    take_batch_request(in, &request);
    uint32_t joint_count = 0;
    if (links != NULL && opx_linkset_get_joint_count(links, &joint_count) != OPX_OK) joint_count = 0;
    /* Mostly the robot's joint count and a few rows, sometimes neither. */
    const size_t joints = take_u8(in) < 240 ? joint_count : take_below(in, MAX_JOINTS + 1);
    const size_t count = take_u8(in) < 240 ? 1 + take_below(in, MAX_ROWS) : take_below(in, MAX_ROWS + 1);
    double rows[MAX_ROWS * MAX_JOINTS] = {0};
    if (joints > MAX_JOINTS) return;
    for (size_t i = 0; i < count * joints; ++i) rows[i] = take_joint_position(in);
    opx_pose base;
    take_base(in, tree, &base);
    uint8_t collided[MAX_ROWS];
    const opx_status status = FUZZ_CALL(opx_query_check_configurations, query, tree, links, rows, count, joints, 0,
                                        &base, 1, 0, &request, collided, NULL, count);
    check_motion_of_rows(api, query, tree, links, rows, count, joints, &base);
    /* An older request's size leaves the later fields at their defaults. */
    if (status != OPX_OK || tree == NULL || request.struct_size != sizeof request) return;
    for (size_t i = 0; i < count; ++i) {
        const int expected =
            single_collides(api->reference[0], tree, links, rows + i * joints, joints, &base, &request);
        if (expected >= 0) FUZZ_REQUIRE(collided[i] == expected);
    }
}

/* A trajectory's obstacle cost (opx_query_trajectory_cost): the link set's
 * rows as waypoints; an accepted answer is a finite cost >= 0 with a
 * finite gradient, the same on a second call. */
void op_query_trajectory_cost(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query *query = take_query(api);
    const opx_octree *tree = take_tree(api);
    const opx_linkset *links = take_linkset(api);
    opx_batch_request batch = OPX_BATCH_REQUEST_INIT;
    take_batch_request(in, &batch);
    opx_trajectory_cost_request request = OPX_TRAJECTORY_COST_REQUEST_INIT;
    request.struct_size = batch.struct_size == sizeof batch ? sizeof request : batch.struct_size;
    request.unknown_policy = batch.unknown_policy;
    request.occupancy_threshold = batch.occupancy_threshold;
    request.obstacle_geometry = batch.obstacle_geometry;
    request.joint_order = batch.joint_order;
    request.activation = take_u8(in) < 240 ? 0.01 + take_u8(in) / 500.0 : take_double(in);
    uint32_t joint_count = 0;
    if (links != NULL && opx_linkset_get_joint_count(links, &joint_count) != OPX_OK) joint_count = 0;
    const size_t joints = take_u8(in) < 240 ? joint_count : take_below(in, MAX_JOINTS + 1);
    const size_t count = take_u8(in) < 240 ? 1 + take_below(in, MAX_ROWS) : take_below(in, MAX_ROWS + 1);
    double rows[MAX_ROWS * MAX_JOINTS] = {0};
    if (joints > MAX_JOINTS) return;
    for (size_t i = 0; i < count * joints; ++i) rows[i] = take_joint_position(in);
    opx_pose base;
    take_base(in, tree, &base);
    double cost = -1.0, again = -1.0, gradient[MAX_ROWS * MAX_JOINTS], second[MAX_ROWS * MAX_JOINTS];
    const size_t capacity = take_u8(in) < 240 ? count : take_below(in, MAX_ROWS + 1);
    const opx_status status = FUZZ_CALL(opx_query_trajectory_cost, query, tree, links, rows, count, joints, 0, &base,
                                        &request, &cost, gradient, capacity);
    if (status != OPX_OK) return;
    FUZZ_REQUIRE(cost >= 0.0 && cost < 1e300);
    for (size_t i = 0; i < count * joints; ++i) FUZZ_REQUIRE(gradient[i] == gradient[i]);
    FUZZ_REQUIRE(opx_query_trajectory_cost(api->reference[0], tree, links, rows, count, joints, 0, &base, &request,
                                           &again, second, capacity) == OPX_OK);
    FUZZ_REQUIRE(again == cost);
}
