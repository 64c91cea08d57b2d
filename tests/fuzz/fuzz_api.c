/*
 * Fuzz target: sequences of C-API calls (see fuzz_api.h; the input's
 * layout is in fuzz_api_ops.h).  Every handle left at the end is
 * destroyed, the tables emptied in an order the input picks.
 */
#include "fuzz_api.h"
#include "fuzz_api_ops.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static const fuzz_operation operations[OP_COUNT] = {
    [OP_OCTREE_CREATE] = op_octree_create,
    [OP_OCTREE_DESTROY] = op_octree_destroy,
    [OP_OCTREE_INSERT] = op_octree_insert,
    [OP_OCTREE_CLEAR] = op_octree_clear,
    [OP_OCTREE_READ] = op_octree_read,
    [OP_OCTREE_IMAGE] = op_octree_image,
    [OP_OCTREE_EXERCISE] = op_octree_exercise,
    [OP_LINKSET_CREATE] = op_linkset_create,
    [OP_LINKSET_DESTROY] = op_linkset_destroy,
    [OP_LINKSET_ADD_LINK] = op_linkset_add_link,
    [OP_LINKSET_ADD_SHAPE] = op_linkset_add_shape,
    [OP_LINKSET_SETTINGS] = op_linkset_settings,
    [OP_LINKSET_SET_POSES] = op_linkset_set_poses,
    [OP_LINKSET_READ] = op_linkset_read,
    [OP_ROBOT_LOAD] = op_robot_load,
    [OP_ROBOT_JOINTS] = op_robot_joints,
    [OP_QUERY_CREATE] = op_query_create,
    [OP_QUERY_DESTROY] = op_query_destroy,
    [OP_QUERY_COLLIDE] = op_query_collide,
    [OP_QUERY_DISTANCE] = op_query_distance,
    [OP_QUERY_PATH] = op_query_path,
    [OP_QUERY_BOXES] = op_query_boxes,
    [OP_QUERY_READ] = op_query_read,
    [OP_QUERY_SPHERES] = op_query_spheres,
    [OP_QUERY_BATCH] = op_query_batch,
    [OP_QUERY_SPHERE_DISTANCE] = op_query_sphere_distance,
    [OP_QUERY_TRAJECTORY_COST] = op_query_trajectory_cost,
    [OP_OCTREE_EDIT] = op_octree_edit,
};

size_t take_slot(fuzz_api *api) { return take_below(&api->in, FUZZ_SLOTS); }

/* Slot FUZZ_SLOTS stands for NULL. */
opx_octree *take_tree(fuzz_api *api) {
    const size_t slot = take_below(&api->in, FUZZ_SLOTS + 1);
    return slot < FUZZ_SLOTS ? api->trees[slot] : NULL;
}

opx_linkset *take_linkset(fuzz_api *api) {
    const size_t slot = take_below(&api->in, FUZZ_SLOTS + 1);
    return slot < FUZZ_SLOTS ? api->linksets[slot] : NULL;
}

opx_query *take_query(fuzz_api *api) {
    const size_t slot = take_below(&api->in, FUZZ_SLOTS + 1);
    return slot < FUZZ_SLOTS ? api->queries[slot] : NULL;
}

uint32_t take_link(fuzz_api *api, const opx_linkset *links) {
    uint32_t count = 0;
    if (links != NULL) FUZZ_CALL(opx_linkset_get_link_count, links, &count);
    const uint8_t kind = take_u8(&api->in);
    if (kind < 224) return (uint32_t)take_below(&api->in, (size_t)count + 1);
    return kind & 1 ? UINT32_MAX : take_u32(&api->in);
}

void take_pose(fuzz_input *in, opx_pose *pose) {
    const uint8_t kind = take_u8(in);
    for (int i = 0; i < 3; ++i)
        pose->position[i] = kind < 192 ? (double)(int8_t)take_u8(in) / 20.0 : take_double(in);
    for (int i = 0; i < 4; ++i)
        pose->orientation[i] = kind < 128 ? (double)(int8_t)take_u8(in) / 64.0 : take_double(in);
}

void find_occupied_targets(const opx_octree *tree, occupied_targets *targets) {
    size_t total = 0;
    targets->count = 0;
    if (tree == NULL) return;
    const opx_status status =
        opx_octree_get_leaves(tree, OPX_MASK_OCCUPIED, targets->leaves, FUZZ_MAX_TARGETS, &total);
    if (status == OPX_OK || status == OPX_ERROR_BUFFER_TOO_SMALL)
        targets->count = total < FUZZ_MAX_TARGETS ? total : FUZZ_MAX_TARGETS;
}

size_t take_stride(fuzz_input *in, size_t element_size) {
    switch (take_u8(in) % 8) {
    case 0:
    case 1: return 0;
    case 2: return element_size;
    case 3: return element_size + 8;
    case 4: return element_size + 3;
    case 5: return element_size / 2;
    case 6: return 1;
    default: return element_size + take_below(in, 64);
    }
}

size_t array_bytes(size_t count, size_t stride, size_t element_size) {
    if (count == 0) return 0;
    const size_t step = stride == 0 ? element_size : stride;
    return (count - 1) * step + element_size;
}

/* In the order the input picks: queries may outlive the maps and link
 * sets they queried, or not. */
static void destroy_everything(fuzz_api *api, uint8_t order) {
    for (int round = 0; round < 3; ++round) {
        switch ((order + round) % 3) {
        case 0:
            for (size_t i = 0; i < FUZZ_SLOTS; ++i) opx_octree_destroy(api->trees[i]);
            break;
        case 1:
            for (size_t i = 0; i < FUZZ_SLOTS; ++i) opx_linkset_destroy(api->linksets[i]);
            break;
        default:
            for (size_t i = 0; i < FUZZ_SLOTS; ++i) opx_query_destroy(api->queries[i]);
            break;
        }
    }
    opx_query_destroy(api->reference[0]);
    opx_query_destroy(api->reference[1]);
}

static void create_references(fuzz_api *api) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    FUZZ_REQUIRE(opx_query_create(&options, &api->reference[0]) == OPX_OK);
    options.engine = OPX_ENGINE_AMORTIZED;
    FUZZ_REQUIRE(opx_query_create(&options, &api->reference[1]) == OPX_OK);
}

/* The next record's arguments become api->in; returns its operation. */
static uint8_t next_record(fuzz_input *program, fuzz_api *api) {
    const uint8_t operation = take_u8(program);
    size_t length = take_u8(program);
    if (length > program->size) length = program->size;
    api->in.data = program->data;
    api->in.size = length;
    program->data += length;
    program->size -= length;
    return operation;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    fuzz_input program = {data, size};
    fuzz_api api;
    memset(&api, 0, sizeof api);
    const uint8_t destroy_order = take_u8(&program);
    create_references(&api);
    for (int step = 0; step < FUZZ_MAX_OPERATIONS && program.size > 0; ++step)
        operations[next_record(&program, &api) % OP_COUNT](&api);
    destroy_everything(&api, destroy_order);
    return 0;
}
