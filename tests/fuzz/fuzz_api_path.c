/* Operations of the call-sequence fuzzer: path queries and a caller's
 * boxes as the map.  See fuzz_api.h. */
#include "fuzz_api.h"
#include "fuzz_api_requests.h"

#include <stdlib.h>

/* Poses laid out as opx_query_path reads them, strides included. */
typedef struct path_poses {
    opx_pose *poses;
    size_t waypoints, pose_stride, waypoint_stride;
} path_poses;

static void take_path_poses(fuzz_input *in, size_t links, path_poses *path) {
    path->waypoints = take_below(in, FUZZ_MAX_WAYPOINTS + 1);
    path->pose_stride = take_stride(in, sizeof(opx_pose));
    const size_t pose_step = path->pose_stride == 0 ? sizeof(opx_pose) : path->pose_stride;
    const size_t row = links * pose_step;
    const uint8_t kind = take_u8(in) % 4;
    path->waypoint_stride = kind == 0 ? 0 : kind == 1 ? row : kind == 2 ? row + 16 : take_below(in, row + 1);
    const size_t waypoint_step = path->waypoint_stride == 0 ? row : path->waypoint_stride;
    const size_t bytes = path->waypoints == 0 || links == 0
                             ? 0 : (path->waypoints - 1) * waypoint_step + array_bytes(links, path->pose_stride, sizeof(opx_pose));
    path->poses = calloc(bytes / sizeof(opx_pose) + 2, sizeof(opx_pose));
    FUZZ_REQUIRE(path->poses != NULL);
    for (size_t w = 0; w < path->waypoints; ++w) {
        for (size_t l = 0; l < links && l < 64; ++l) {
            opx_pose pose;
            take_pose(in, &pose);
            memcpy((char *)path->poses + w * waypoint_step + l * pose_step, &pose, sizeof pose);
        }
    }
}

void op_query_path(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query *query = take_query(api);
    const opx_octree *tree = take_tree(api);
    const opx_linkset *links = take_linkset(api);
    uint32_t link_count = 0;
    if (links != NULL) FUZZ_CALL(opx_linkset_get_link_count, links, &link_count);
    path_poses path;
    take_path_poses(in, link_count, &path);
    opx_path_request request = OPX_PATH_REQUEST_INIT;
    take_path_request(in, &request);
    opx_path_result result = OPX_PATH_RESULT_INIT;
    result.struct_size = take_struct_size(in, sizeof result);
    const opx_pose *poses = take_u8(in) < 240 ? path.poses : NULL;
    FUZZ_CALL(opx_query_path, query, tree, links, poses, path.waypoints, path.pose_stride, path.waypoint_stride,
              &request, &result);
    if (tree != NULL && links != NULL) {
        /* Both engines answer the same. */
        opx_path_result answers[2] = {OPX_PATH_RESULT_INIT, OPX_PATH_RESULT_INIT};
        opx_status statuses[2];
        for (int engine = 0; engine < 2; ++engine)
            statuses[engine] = FUZZ_CALL(opx_query_path, api->reference[engine], tree, links, poses, path.waypoints,
                                         path.pose_stride, path.waypoint_stride, &request, &answers[engine]);
        FUZZ_REQUIRE(statuses[0] == statuses[1]);
        if (statuses[0] == OPX_OK) {
            FUZZ_REQUIRE(answers[0].collided == answers[1].collided);
            FUZZ_REQUIRE(answers[0].first_colliding_waypoint == answers[1].first_colliding_waypoint);
        }
    }
    free(path.poses);
}

/* Binds boxes (min <= max mostly) and runs collision or distance on them. */
void op_query_boxes(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query *query = take_query(api);
    const size_t count = take_below(in, FUZZ_MAX_BOXES + 1);
    const size_t stride = take_stride(in, 6 * sizeof(double));
    const size_t step = stride == 0 ? 6 * sizeof(double) : stride;
    double *boxes = calloc((count + 1) * (step + 48) / sizeof(double) + 1, sizeof(double));
    FUZZ_REQUIRE(boxes != NULL);
    for (size_t i = 0; step % sizeof(double) == 0 && step >= 48 && i < count; ++i) {
        double *box = boxes + i * step / sizeof(double);
        for (int axis = 0; axis < 3; ++axis) {
            box[axis] = take_u8(in) < 224 ? (double)(int8_t)take_u8(in) / 20.0 : take_double(in);
            box[axis + 3] = take_u8(in) < 224 ? box[axis] + take_u8(in) / 50.0 : take_double(in);
        }
    }
    if (take_u8(in) < 160)
        FUZZ_CALL(opx_query_bind_boxes, query, take_u8(in) < 240 ? boxes : NULL, count, stride);
    free(boxes);
    const opx_linkset *links = take_linkset(api);
    if (take_bool(in)) {
        opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
        take_collision_request(in, &request);
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        if (FUZZ_CALL(opx_query_collide_boxes, query, links, &request, &result) == OPX_OK)
            check_collision_result(&request, &result);
    } else {
        opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
        take_distance_request(in, &request);
        opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
        if (FUZZ_CALL(opx_query_distance_boxes, query, links, &request, &result) == OPX_OK)
            check_distance_result(&request, &result);
    }
}
