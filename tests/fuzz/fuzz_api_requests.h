/*
 * Fuzzed query requests of the call-sequence fuzzer, and the checks of
 * their results that query.h's documentation allows.
 */
#ifndef OPX_FUZZ_API_REQUESTS_H
#define OPX_FUZZ_API_REQUESTS_H

#include "fuzz_api.h"

void take_collision_request(fuzz_input *in, opx_collision_request *request);
void take_distance_request(fuzz_input *in, opx_distance_request *request);
void take_path_request(fuzz_input *in, opx_path_request *request);
void take_sphere_request(fuzz_input *in, opx_sphere_request *request);
/* Collisions only (no distance, no self-collision), on 1 to 3 threads. */
void take_batch_request(fuzz_input *in, opx_batch_request *request);

/* Whether the links touch the map, as a yes/no opx_query_collide (no
 * contacts) with these settings says; -1 when it refuses. */
int yes_no_collides(opx_query *query, const opx_octree *tree, const opx_linkset *links, int32_t unknown_policy,
                    double occupancy_threshold, int32_t obstacle_geometry);

/* request NULL: the defaults. */
void check_collision_result(const opx_collision_request *request, const opx_collision_result *result);
void check_distance_result(const opx_distance_request *request, const opx_distance_result *result);
/* Two engines' answers to one exact distance request. */
void check_same_distance(const opx_distance_result *a, const opx_distance_result *b);

#endif /* OPX_FUZZ_API_REQUESTS_H */
