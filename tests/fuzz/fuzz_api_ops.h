/*
 * The operations of the call-sequence fuzzer, by number.  An input is
 *   byte 0: the order in which the handle tables are emptied at the end
 *   then records: [operation] [length] [length bytes of arguments]
 * An operation reads its arguments from its own record only (zeros past
 * its end), so a mutation of one record leaves the others' meaning alone.
 * Shared with the seed generator, which writes such records.
 */
#ifndef OPX_FUZZ_API_OPS_H
#define OPX_FUZZ_API_OPS_H

enum fuzz_api_op {
    OP_OCTREE_CREATE,
    OP_OCTREE_DESTROY,
    OP_OCTREE_INSERT,
    OP_OCTREE_CLEAR,
    OP_OCTREE_READ,
    OP_OCTREE_IMAGE,
    OP_OCTREE_EXERCISE,
    OP_LINKSET_CREATE,
    OP_LINKSET_DESTROY,
    OP_LINKSET_ADD_LINK,
    OP_LINKSET_ADD_SHAPE,
    OP_LINKSET_SETTINGS,
    OP_LINKSET_SET_POSES,
    OP_LINKSET_READ,
    OP_ROBOT_LOAD,
    OP_ROBOT_JOINTS,
    OP_QUERY_CREATE,
    OP_QUERY_DESTROY,
    OP_QUERY_COLLIDE,
    OP_QUERY_DISTANCE,
    OP_QUERY_PATH,
    OP_QUERY_BOXES,
    OP_QUERY_READ,
    OP_QUERY_SPHERES,
    OP_QUERY_BATCH,
    OP_QUERY_SPHERE_DISTANCE,
    OP_QUERY_TRAJECTORY_COST,
    OP_OCTREE_EDIT,
    OP_COUNT
};

#endif /* OPX_FUZZ_API_OPS_H */
