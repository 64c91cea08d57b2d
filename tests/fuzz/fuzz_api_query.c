/* Operations of the call-sequence fuzzer on query contexts: collision,
 * distance and what a context holds afterwards.  See fuzz_api.h. */
#include "fuzz_api.h"
#include "fuzz_api_requests.h"

void op_query_create(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.struct_size = take_struct_size(in, sizeof options);
    const uint8_t engine = take_u8(in);
    options.engine = engine < 120 ? OPX_ENGINE_DIRECT : engine < 240 ? OPX_ENGINE_AMORTIZED : (int32_t)engine;
    /* Each refinement step costs a tree walk per query: a few suffice. */
    options.refine_steps = (uint32_t)take_below(in, FUZZ_MAX_REFINE_STEPS + 1);
    const uint8_t bits = take_u8(in);
    options.morton_bits = bits < 224 ? 1 + bits % 21 : bits % 2 ? 0 : 22;
    opx_query *query = NULL;
    const opx_status status = FUZZ_CALL(opx_query_create, take_u8(in) < 224 ? &options : NULL, &query);
    FUZZ_REQUIRE((status == OPX_OK) == (query != NULL));
    if (query == NULL) return;
    const size_t slot = take_slot(api);
    opx_query_destroy(api->queries[slot]);
    api->queries[slot] = query;
}

void op_query_destroy(fuzz_api *api) {
    const size_t slot = take_slot(api);
    opx_query_destroy(api->queries[slot]);
    api->queries[slot] = NULL;
}

void op_query_collide(fuzz_api *api) {
    opx_query *query = take_query(api);
    const opx_octree *tree = take_tree(api);
    const opx_linkset *links = take_linkset(api);
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    take_collision_request(&api->in, &request);
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    result.struct_size = take_struct_size(&api->in, sizeof result);
    const int with_request = take_u8(&api->in) < 240;
    const opx_status status =
        FUZZ_CALL(opx_query_collide, query, tree, links, with_request ? &request : NULL, &result);
    if (status == OPX_OK && result.struct_size == sizeof result)
        check_collision_result(with_request ? &request : NULL, &result);
    if (tree == NULL || links == NULL) return;
    /* Both engines answer the same. */
    opx_collision_result answers[2] = {OPX_COLLISION_RESULT_INIT, OPX_COLLISION_RESULT_INIT};
    opx_status statuses[2];
    for (int engine = 0; engine < 2; ++engine)
        statuses[engine] = FUZZ_CALL(opx_query_collide, api->reference[engine], tree, links,
                                     with_request ? &request : NULL, &answers[engine]);
    FUZZ_REQUIRE(statuses[0] == statuses[1]);
    if (statuses[0] != OPX_OK) return;
    FUZZ_REQUIRE(answers[0].collided == answers[1].collided);
    if (status == OPX_OK && result.struct_size >= 8) FUZZ_REQUIRE(result.collided == answers[0].collided);
}

void op_query_distance(fuzz_api *api) {
    opx_query *query = take_query(api);
    const opx_octree *tree = take_tree(api);
    const opx_linkset *links = take_linkset(api);
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    take_distance_request(&api->in, &request);
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    result.struct_size = take_struct_size(&api->in, sizeof result);
    const int with_request = take_u8(&api->in) < 240;
    const opx_status status =
        FUZZ_CALL(opx_query_distance, query, tree, links, with_request ? &request : NULL, &result);
    if (status == OPX_OK && result.struct_size == sizeof result)
        check_distance_result(with_request ? &request : NULL, &result);
    if (tree == NULL || links == NULL) return;
    opx_distance_result answers[2] = {OPX_DISTANCE_RESULT_INIT, OPX_DISTANCE_RESULT_INIT};
    opx_status statuses[2];
    for (int engine = 0; engine < 2; ++engine)
        statuses[engine] = FUZZ_CALL(opx_query_distance, api->reference[engine], tree, links,
                                     with_request ? &request : NULL, &answers[engine]);
    FUZZ_REQUIRE(statuses[0] == statuses[1]);
    const int exact = !with_request || (request.abs_err == 0.0 && request.rel_err == 0.0);
    if (statuses[0] == OPX_OK && exact) check_same_distance(&answers[0], &answers[1]);
}

/* Contacts, cost boxes, per-link distances and statistics of a context. */
void op_query_read(fuzz_api *api) {
    fuzz_input *in = &api->in;
    opx_query *query = take_query(api);
    const size_t index = take_u8(in) < 224 ? take_below(in, 4) : take_u32(in);
    opx_contact contact = OPX_CONTACT_INIT;
    contact.struct_size = take_struct_size(in, sizeof contact);
    FUZZ_CALL(opx_query_get_contact, query, index, &contact);
    opx_cost_box box = OPX_COST_BOX_INIT;
    box.struct_size = take_struct_size(in, sizeof box);
    FUZZ_CALL(opx_query_get_cost_box, query, index, &box);
    double distances[8];
    size_t count = 0;
    FUZZ_CALL(opx_query_get_link_distances, query, take_bool(in) ? distances : NULL, take_below(in, 9), &count);
    opx_query_stats stats = OPX_QUERY_STATS_INIT;
    stats.struct_size = take_struct_size(in, sizeof stats);
    FUZZ_CALL(opx_query_get_stats, query, &stats);
}
