/*
 * The C-API call-sequence fuzzer: the input is a program of calls (its
 * layout is in fuzz_api_ops.h) on a few octrees, link sets and query
 * contexts held in handle tables.  Each operation reads its arguments from
 * its record (fuzz_input.h), calls the API and checks the status
 * (fuzz_check.h).  A destroyed handle leaves its
 * table at once, so no call ever gets a dangling pointer (the API does not
 * promise to survive use after free); a NULL handle is passed on purpose.
 *
 * Work per input is bounded (operations, points, shapes, waypoints, boxes,
 * the length of inserted rays), so an input runs in milliseconds.
 */
#ifndef OPX_FUZZ_API_H
#define OPX_FUZZ_API_H

#include "fuzz_check.h"
#include "fuzz_input.h"

#define FUZZ_SLOTS 3
#define FUZZ_MAX_OPERATIONS 48
#define FUZZ_MAX_POINTS 24
#define FUZZ_MAX_RAY_CELLS 24.0 /* longest inserted ray, in cells */
#define FUZZ_MAX_VERTICES 16
#define FUZZ_MAX_TRIANGLES 8
#define FUZZ_MAX_WAYPOINTS 4
#define FUZZ_MAX_BOXES 16
#define FUZZ_MAX_REFINE_STEPS 64

typedef struct fuzz_api {
    fuzz_input in;
    opx_octree *trees[FUZZ_SLOTS];
    opx_linkset *linksets[FUZZ_SLOTS];
    opx_query *queries[FUZZ_SLOTS];
    /* One context per engine (direct, amortized) that answers every
     * collision, distance and path query again: their answers must agree. */
    opx_query *reference[2];
} fuzz_api;

typedef void (*fuzz_operation)(fuzz_api *api);

/* ---- Arguments (fuzz_api.c) -------------------------------------------- */

size_t take_slot(fuzz_api *api);
/* A handle of the table (possibly an empty slot), or NULL on purpose. */
opx_octree *take_tree(fuzz_api *api);
opx_linkset *take_linkset(fuzz_api *api);
opx_query *take_query(fuzz_api *api);
/* A link index: mostly one of the set's links, sometimes beyond them. */
uint32_t take_link(fuzz_api *api, const opx_linkset *links);
/* A pose: mostly a valid one (small position, any non-zero quaternion). */
void take_pose(fuzz_input *in, opx_pose *pose);
/* Where spheres and robots go: near the map's first occupied leaves. */
enum { FUZZ_MAX_TARGETS = 16 };
typedef struct {
    opx_leaf leaves[FUZZ_MAX_TARGETS];
    size_t count;
} occupied_targets;
void find_occupied_targets(const opx_octree *tree, occupied_targets *targets);
/* A stride for elements of `element_size` bytes: 0 (packed), the size, a
 * larger one, an unaligned one, or one too small. */
size_t take_stride(fuzz_input *in, size_t element_size);
/* Bytes that a (pointer, count, stride) array of `element_size`-byte
 * elements reaches; stride 0 means element_size. */
size_t array_bytes(size_t count, size_t stride, size_t element_size);

/* ---- Operations -------------------------------------------------------- */

/* fuzz_api_octree.c */
void op_octree_create(fuzz_api *api);
void op_octree_destroy(fuzz_api *api);
void op_octree_insert(fuzz_api *api);
void op_octree_clear(fuzz_api *api);
void op_octree_read(fuzz_api *api);
void op_octree_image(fuzz_api *api);
void op_octree_exercise(fuzz_api *api);
void op_octree_edit(fuzz_api *api);

/* fuzz_api_linkset.c */
void op_linkset_create(fuzz_api *api);
void op_linkset_destroy(fuzz_api *api);
void op_linkset_add_link(fuzz_api *api);
void op_linkset_add_shape(fuzz_api *api);
void op_linkset_settings(fuzz_api *api);
void op_linkset_set_poses(fuzz_api *api);
void op_linkset_read(fuzz_api *api);

/* fuzz_api_robot.c */
void op_robot_load(fuzz_api *api);
void op_robot_joints(fuzz_api *api);
/* A joint position: mostly small (+-3.2), sometimes any double. */
double take_joint_position(fuzz_input *in);

/* fuzz_api_query.c */
void op_query_create(fuzz_api *api);
void op_query_destroy(fuzz_api *api);
void op_query_collide(fuzz_api *api);
void op_query_distance(fuzz_api *api);
void op_query_read(fuzz_api *api);
void op_query_spheres(fuzz_api *api);
void op_query_sphere_distance(fuzz_api *api);

/* fuzz_api_path.c */
void op_query_path(fuzz_api *api);
void op_query_boxes(fuzz_api *api);

/* fuzz_api_batch.c */
void op_query_batch(fuzz_api *api);
void op_query_trajectory_cost(fuzz_api *api);

#endif /* OPX_FUZZ_API_H */
