/*
 * Many questions per call, as a motion planner asks them: many joint
 * configurations of one robot (opx_query_check_configurations) and
 * joint-space motions (opx_query_check_motion, opx_query_check_motions)
 * against one map.
 *
 * The robot is a link set made from URDF (robot.h); joint vectors hold
 * joint_count values (radians or metres, each finite and within +-1e6) in
 * one of two orders, which the request's joint_order field chooses:
 *   - model order: every joint, as opx_linkset_set_joint_positions takes
 *     them (fixed, floating and planar joints' values ignored, mimic joints
 *     following their masters); joint_count is the joint count;
 *   - active order: the active joints alone, as
 *     opx_linkset_set_active_joint_positions takes them; joint_count is the
 *     active joint count.
 * OPX_JOINTS_BY_COUNT (the default) tells them apart by joint_count: the
 * joint count means model order, the active joint count active order.
 * This is never ambiguous: the active joints are some of the joints in
 * the same order, so the two counts are equal only when every joint is
 * active, and the two orders are then one.  OPX_JOINTS_MODEL and
 * OPX_JOINTS_ACTIVE insist on one order (another joint_count is an invalid
 * argument).  Both orders give the same answers for the same positions of
 * the active joints.  Forward kinematics runs inside the call on the query's own
 * copies of the link set: the caller's link set is not moved (its poses
 * and joint positions stay as they are) and is only read, so any number of
 * queries may check configurations of one link set at once.  Links added
 * with opx_linkset_add_link after loading keep their current pose.
 *
 * A configuration collides when an enabled link touches an obstacle cell
 * (the rules of opx_query_collide: padding included, touching collides)
 * or, on a query with a world (world.h, opx_query_set_world), one of its
 * enabled objects, or, with self_collision, when two links of an enabled
 * pair touch (opx_query_self_collide).  With a world the octree may be
 * NULL (the objects alone); distances are then the least over the octree
 * and the objects, and the objects add no cost.  The answers are those of the single calls at
 * the same joint positions (opx_linkset_set_joint_positions, then
 * opx_query_collide / opx_query_distance), whatever the thread count.
 *
 * Threads: max_threads workers split the configurations (or motions); 1
 * (the default) runs on the caller's thread, 0 takes one per hardware
 * thread.  The threads come from a pool the library keeps between calls
 * (started by the first call that needs them; a thread left without work
 * checks for more for 50 microseconds, then sleeps), so handing work to
 * them costs microseconds: two threads pay from about four configurations
 * of the PR2 a call.  Each worker has its own engine and scratch memory, kept in the
 * opx_query between calls (with OPX_ENGINE_AMORTIZED, each worker builds
 * its own trees of a frame once), so a warm call allocates nothing per
 * configuration.  Each worker also keeps its own copy of the link set
 * (shapes and meshes: a few MB for the PR2), made again only when the link
 * set changes in more than its poses.  These calls leave the query's results (contacts, cost
 * boxes, link distances) as they were, but for opx_query_check_motion with
 * compute_cost, which leaves them as opx_query_path does (its cost boxes,
 * no contacts).
 *
 * Robots of spheres: a link set whose every collision shape is a sphere
 * (attached objects' too), asked for collisions with the octree alone (no
 * distance, self_collision, world or cost; unknown space free), is
 * checked sphere by sphere on the map's obstacle grid, as
 * opx_query_collide_spheres checks spheres (spheres.h), with the same
 * answers: about 10 ns a sphere at 2 cm.  The first such call after the
 * map changed builds the grid (some hundred microseconds for a 640x480
 * frame at 2 cm); the map keeps it for every later call and thread.
 *
 * Arrays: joint vectors are rows of joint_count doubles, `stride` bytes
 * apart (0: packed, joint_count * 8 bytes); base poses are opx_pose
 * elements `base_pose_stride` bytes apart (0: packed).  base_pose_count 0
 * puts the root link at the map origin (base_poses may be NULL), 1 gives
 * every row that root pose, and the row count gives each row its own.
 * Output arrays hold `capacity` elements; a capacity below the row count
 * is OPX_ERROR_BUFFER_TOO_SMALL and nothing is checked.  On any error the
 * output arrays' contents are unspecified.
 */
#ifndef OCTOPROX_BATCH_H
#define OCTOPROX_BATCH_H

#include "common.h"
#include "linkset.h"
#include "octree.h"
#include "query.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The order of joint vectors (opx_batch_request.joint_order,
 * opx_motion_request.joint_order; see above). */
/** Model or active order, told apart by joint_count (the default). */
#define OPX_JOINTS_BY_COUNT 0
/** Every joint in model order. */
#define OPX_JOINTS_MODEL 1
/** The active joints alone, in model order. */
#define OPX_JOINTS_ACTIVE 2

typedef struct opx_batch_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< as in opx_collision_request */
    double occupancy_threshold; /**< as in opx_collision_request; 0: the octree's */
    int32_t self_collision;     /**< 1: also the link set's own enabled pairs */
    /** 1: out_distances gets each configuration's minimum distance between
     * the enabled links and the obstacles (metres, padding included, 0 when
     * touching or overlapping; with self_collision, the smaller of that and
     * the self distance), and no check stops at the first contact. */
    int32_t compute_distance;
    /** With compute_distance: obstacles farther than this (metres) are not
     * searched, the distance is then the cutoff ("at least").  0 (default)
     * or +infinity: no cutoff. */
    double distance_cutoff;
    uint32_t max_threads;       /**< 1 (default): the caller's thread; 0: one per hardware thread */
    int32_t obstacle_geometry;  /**< OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS */
    /** The order of the rows: OPX_JOINTS_BY_COUNT (default),
     * OPX_JOINTS_MODEL or OPX_JOINTS_ACTIVE (see above). */
    int32_t joint_order;
    int32_t reserved0;          /**< padding; keep 0 */
} opx_batch_request;

#define OPX_BATCH_REQUEST_INIT {sizeof(opx_batch_request), OPX_UNKNOWN_FREE, 0.0, 0, 0, 0.0, 1, \
    OPX_OBSTACLE_CELLS, OPX_JOINTS_BY_COUNT, 0}
OPX_API opx_status opx_batch_request_init(opx_batch_request *request, size_t size);

/**
 * Checks `configuration_count` joint vectors (rows of `positions`, see
 * above) of the link set against the octree.  out_collided[i] gets 1 when
 * configuration i collides, else 0 (it stops at the first contact unless
 * distances are asked); with compute_distance, out_distances[i] its
 * minimum distance (out_distances may be NULL otherwise).  joint_count
 * is the joint count or the active joint count, as request->joint_order
 * allows (above).  request may be NULL (defaults).
 * configuration_count 0 is an invalid argument (an empty batch is most
 * often a caller's slip).
 */
OPX_API opx_status opx_query_check_configurations(opx_query *query, const opx_octree *tree,
                                                  const opx_linkset *links, const double *positions,
                                                  size_t configuration_count, size_t joint_count,
                                                  size_t stride, const opx_pose *base_poses,
                                                  size_t base_pose_count, size_t base_pose_stride,
                                                  const opx_batch_request *request,
                                                  uint8_t *out_collided, double *out_distances,
                                                  size_t capacity);

/* ---- Joint-space motions ---------------------------------------------- */

/* How a motion is checked (opx_motion_request.check).
 *
 * OPX_MOTION_SAMPLED checks the configurations `resolution` apart (below);
 * the robot is not checked between them, so an obstacle thinner than a
 * link's travel from one sample to the next may be passed through unseen.
 *
 * OPX_MOTION_CERTIFIED checks the whole segment, every parameter s in
 * [0, 1] of start + s (goal - start), by conservative advancement on exact
 * distances (docs/geometry.md): from a configuration where each enabled
 * link is d away from the obstacles (the octree's cells or point extents
 * as obstacle_geometry says, unknown space as unknown_policy says, the
 * world's enabled objects; padding included), the links cannot reach
 * them before each has moved d, and a bound on how far a link's points
 * move per unit of each joint (from the joint tree: distances from the
 * joint axes to the farthest point of the link's shapes, 1 for a
 * prismatic joint) says when that can first happen; the check advances
 * there and measures again.  With self_collision the same holds for the
 * enabled pairs of links, by a bound on their relative displacement.
 *  - "free" (collided 0) means no configuration of the segment, at any
 *    parameter, collides under the rules of opx_query_collide and
 *    opx_query_self_collide (touching collides), rounding of the exact
 *    distances (docs/geometry.md) accounted for.
 *  - "collides" (collided 1) reports first_collision_fraction f: the
 *    configuration at f collides, where in this mode a configuration also
 *    counts as colliding when its distance to an obstacle (or between an
 *    enabled pair) is at most 1e-8 m (OPX_MOTION_CONTACT_DISTANCE, a
 *    hair above the 1e-9 m touch tolerance, so that a motion that grazes
 *    an obstacle ends); and no configuration before f - tolerance
 *    collides (the first colliding fraction lies in [f - tolerance, f];
 *    f = 0 when the start collides).
 * resolution does not apply in this mode, and compute_cost is an invalid
 * argument with it.  steps gets the advancement steps taken,
 * configurations_checked the configurations measured.  A check costs
 * few distance queries for a motion far from every obstacle (the steps
 * double while nothing is near: four take all of it) and more the closer the
 * motion passes to one: near a contact the steps shrink with the
 * distance until they are shorter than tolerance.  A motion that needs
 * more than 1e6 steps (one that passes within a hair of an obstacle over
 * a long stretch) is refused with OPX_ERROR_UNSUPPORTED, naming the
 * parameter reached. */
/** Configurations `resolution` apart (the default). */
#define OPX_MOTION_SAMPLED 0
/** The whole segment, by conservative advancement (above). */
#define OPX_MOTION_CERTIFIED 1
/** Metres: in OPX_MOTION_CERTIFIED, a configuration this close collides. */
#define OPX_MOTION_CONTACT_DISTANCE 1e-8

typedef struct opx_motion_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< as in opx_collision_request */
    double occupancy_threshold; /**< as in opx_collision_request; 0: the octree's */
    /** The largest step of any joint between two checked configurations
     * (radians or metres, > 0; default 0.01).  A motion from start to goal
     * is checked at n + 1 configurations, n = ceil(max over joints of
     * |goal - start| / resolution) (at least 1; mimic joints by their own
     * positions), configuration i being start + (i / n) (goal - start), the
     * goal itself for i = n.  At most 1e7 steps per motion. */
    double resolution;
    int32_t self_collision;     /**< 1: also the link set's own enabled pairs */
    /** opx_query_check_motion only: 1 also gives the cost of uncertain and
     * unknown space the motion sweeps through, every configuration checked
     * (as opx_query_path with compute_cost over the n + 1 configurations:
     * the boxes are held by the query, opx_query_get_cost_box).  The
     * configurations' link poses are held during the call: (n + 1) x
     * links may be at most 2^21 (2,097,152), else an invalid argument
     * naming compute_cost.  Fields below as in opx_collision_request. */
    int32_t compute_cost;
    uint32_t max_cost_boxes;    /**< the costliest boxes kept (default 16) */
    uint32_t max_threads;       /**< opx_query_check_motions: 1 (default) or 0, as above */
    double unknown_probability; /**< 0.5 */
    double region_min[3];
    double region_max[3];
    int32_t obstacle_geometry;  /**< OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS */
    int32_t reserved0;          /**< padding; keep 0 */
    /** The order of start and goal vectors: OPX_JOINTS_BY_COUNT (default),
     * OPX_JOINTS_MODEL or OPX_JOINTS_ACTIVE (see above).  The resolution
     * applies to every moving joint, mimic joints included, in both. */
    int32_t joint_order;
    int32_t reserved1;          /**< padding; keep 0 */
    /** How the motion is checked: OPX_MOTION_SAMPLED (default) or
     * OPX_MOTION_CERTIFIED (see above). */
    int32_t check;
    int32_t reserved2;          /**< padding; keep 0 */
    /** OPX_MOTION_CERTIFIED only: the width of the bracket of the first
     * colliding fraction, a fraction of the motion (> 0 and <= 1; default
     * 1e-3). */
    double tolerance;
} opx_motion_request;

#define OPX_MOTION_REQUEST_INIT {sizeof(opx_motion_request), OPX_UNKNOWN_FREE, 0.0, 0.01, 0, 0, \
    16, 1, 0.5, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, OPX_OBSTACLE_CELLS, 0, OPX_JOINTS_BY_COUNT, 0, \
    OPX_MOTION_SAMPLED, 0, 1e-3}
OPX_API opx_status opx_motion_request_init(opx_motion_request *request, size_t size);

typedef struct opx_motion_result {
    uint32_t struct_size;
    int32_t collided;                /**< 1: some configuration of the motion collides */
    /** Where the first colliding configuration lies: i / n in [0, 1]; -1
     * when none collides.  OPX_MOTION_CERTIFIED: see above. */
    double first_collision_fraction;
    /** n: the motion is checked at n + 1 configurations
     * (OPX_MOTION_CERTIFIED: the advancement steps) */
    uint64_t steps;
    /** Configurations checked: the ends first, then ever finer midpoints,
     * none beyond the first collision found so far (all with compute_cost). */
    uint64_t configurations_checked;
    double total_cost;               /**< with compute_cost: m^3, over all cells swept */
    uint64_t cost_box_count;         /**< held by the query (opx_query_get_cost_box) */
    uint64_t cost_boxes_found;       /**< all cells swept */
} opx_motion_result;

#define OPX_MOTION_RESULT_INIT {sizeof(opx_motion_result), 0, -1.0, 0, 0, 0.0, 0, 0}
OPX_API opx_status opx_motion_result_init(opx_motion_result *result, size_t size);

/**
 * Checks the straight joint-space motion from `start` to `goal` (joint_count
 * values each, model or active order as above) at the request's
 * resolution, the root link at base_pose (map frame; NULL: the origin).
 * request may be NULL (defaults).
 */
OPX_API opx_status opx_query_check_motion(opx_query *query, const opx_octree *tree,
                                          const opx_linkset *links, const double *start,
                                          const double *goal, size_t joint_count,
                                          const opx_pose *base_pose,
                                          const opx_motion_request *request,
                                          opx_motion_result *out_result);

/**
 * Checks `motion_count` motions, row m of `starts` to row m of `goals`
 * (both `stride` bytes per row, see above), as opx_query_check_motion
 * does (compute_cost is not available here).  out_collided[m] gets 1 when
 * motion m collides; out_first_fractions[m] (may be NULL) its first
 * colliding fraction, -1 when none.  A planner's edges between vertices
 * held in one array of (N, 2, joint_count) doubles go in without a copy:
 * starts = the array, goals = starts + joint_count, stride =
 * 2 * joint_count * 8.  motion_count 0 is an invalid argument.
 */
OPX_API opx_status opx_query_check_motions(opx_query *query, const opx_octree *tree,
                                           const opx_linkset *links, const double *starts,
                                           const double *goals, size_t motion_count,
                                           size_t joint_count, size_t stride,
                                           const opx_pose *base_poses, size_t base_pose_count,
                                           size_t base_pose_stride,
                                           const opx_motion_request *request,
                                           uint8_t *out_collided, double *out_first_fractions,
                                           size_t capacity);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_BATCH_H */
