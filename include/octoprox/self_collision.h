/*
 * Self-collision: a link set against itself, at its current poses.
 *
 * Which pairs are checked: every pair of two different links, both
 * enabled (opx_linkset_set_link_enabled) and with shapes, except the pairs
 * disabled in the link set: the SRDF's <disable_collisions> pairs
 * (opx_urdf_options.srdf_path) start disabled, and
 * opx_linkset_set_pair_enabled turns any pair off or on.  Links joined by a
 * joint are NOT skipped implicitly (MoveIt's SRDFs list them as "Adjacent");
 * opx_linkset_disable_never_colliding_pairs disables, by sampling, the
 * pairs that never collide, as MoveIt's setup assistant does.  The shapes
 * of one link never collide with each other.  Objects attached to links
 * (linkset.h) are checked with every enabled link but their own and their
 * touch links, whatever the link pairs say, and with the objects attached
 * to other links; contacts name them (attached_a, attached_b).
 *
 * Geometry: as against the map, shapes are padded (the link's padding plus
 * the set's global padding, on both sides of a pair), touching counts
 * (distance <= 1e-9 m, closed sets), and a mesh is a surface: a shape
 * wholly inside a closed mesh touches none of its triangles.  Accuracy as
 * in docs/geometry.md: exact to rounding between polytopes (boxes, hulls,
 * meshes, spheres and capsules, whose cores are a point and a segment),
 * within about 1e-7 of the distance with a cylinder.
 *
 * Cost: a broad phase over the links' bounding boxes (sort and sweep), then
 * the shapes' boxes, then the exact tests; meshes are walked through their
 * triangle trees without being placed.  Without contacts (max_contacts 0
 * or 1) the check stops at the first touching pair.  The PR2 with its
 * SRDF at random configurations: about 22 us per check on one core, 1 ms
 * per distance (which places the meshes it measures).
 */
#ifndef OCTOPROX_SELF_COLLISION_H
#define OCTOPROX_SELF_COLLISION_H

#include "common.h"
#include "linkset.h"
#include "query.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct opx_self_collision_request {
    uint32_t struct_size;
    /** 0: answer yes/no only; 1 (default): stop at the first touching pair
     * of shapes and report it; N: collect up to N contacts, one per
     * touching pair of shapes (UINT32_MAX: all). */
    uint32_t max_contacts;
    /** 1: each contact also gets its penetration depth, normal and point. */
    int32_t compute_penetration;
    int32_t reserved0;
} opx_self_collision_request;

#define OPX_SELF_COLLISION_REQUEST_INIT {sizeof(opx_self_collision_request), 1, 0, 0}
OPX_API opx_status opx_self_collision_request_init(opx_self_collision_request *request, size_t size);

typedef struct opx_self_collision_result {
    uint32_t struct_size;
    int32_t collided;        /**< 1 when two shapes of a checked pair of links touch */
    uint64_t contact_count;  /**< contacts held by the query (opx_query_get_self_contact) */
    /** 1 when a touching pair beyond the first max_contacts was left out
     * (with max_contacts 0 or 1 the check stops at the first: 0). */
    int32_t truncated;
    uint32_t reserved0;
    uint64_t link_pairs;     /**< checked pairs of links whose bounding boxes overlap */
    uint64_t narrow_tests;   /**< exact tests between convex pieces (a cost measure) */
} opx_self_collision_result;

#define OPX_SELF_COLLISION_RESULT_INIT {sizeof(opx_self_collision_result), 0, 0, 0, 0, 0, 0}
OPX_API opx_status opx_self_collision_result_init(opx_self_collision_result *result, size_t size);

/** Two shapes of two links that touch; link_a < link_b. */
typedef struct opx_self_contact {
    uint32_t struct_size;
    uint32_t link_a;         /**< indices in the link set */
    uint32_t shape_a;        /**< index within link_a */
    uint32_t link_b;
    uint32_t shape_b;
    uint32_t reserved0;
    /** With compute_penetration (else zeros): how deep the padded shapes
     * overlap (metres, >= 0; 0 when only touching), the unit direction
     * link_a went into link_b (moving link_a by -depth * normal, or link_b
     * by +depth * normal, separates the pair), and the contact point:
     * midway between each shape's point deepest in the other, map frame.
     * For a mesh, its deepest triangle. */
    double depth;
    double normal[3];
    double position[3];
    /** The objects attached to link_a and link_b (linkset.h: their indices)
     * whose shapes touch, shape_a or shape_b then being the shape's index
     * within that object; -1: one of the link's own shapes. */
    int32_t attached_a;
    int32_t attached_b;
} opx_self_contact;

#define OPX_SELF_CONTACT_INIT {sizeof(opx_self_contact), 0, 0, 0, 0, 0, 0.0, {0.0, 0.0, 0.0}, \
    {0.0, 0.0, 0.0}, -1, -1}
OPX_API opx_status opx_self_contact_init(opx_self_contact *contact, size_t size);

/**
 * Does the link set (its checked pairs, padding included, at the current
 * poses) collide with itself?  request may be NULL (defaults).  The
 * contacts stay in the query until its next self-collision query; the
 * contacts of map queries are kept apart (opx_query_get_contact).
 */
OPX_API opx_status opx_query_self_collide(opx_query *query, const opx_linkset *links,
                                          const opx_self_collision_request *request,
                                          opx_self_collision_result *out_result);
/** Contact `index` (< contact_count) of the last self-collision query. */
OPX_API opx_status opx_query_get_self_contact(const opx_query *query, size_t index,
                                              opx_self_contact *out_contact);

typedef struct opx_self_distance_request {
    uint32_t struct_size;
    /** 1: when shapes overlap, the distance is minus the deepest penetration
     * over the touching pairs, with the witnesses at each shape's point
     * deepest in the other.  0 (default): overlap is distance 0. */
    int32_t signed_distance;
    /** Pairs farther than this (metres) are not measured: the result is then
     * found = 0, distance = cutoff ("at least cutoff").  0 (default) or
     * +infinity: no cutoff. */
    double cutoff;
} opx_self_distance_request;

#define OPX_SELF_DISTANCE_REQUEST_INIT {sizeof(opx_self_distance_request), 0, 0.0}
OPX_API opx_status opx_self_distance_request_init(opx_self_distance_request *request, size_t size);

typedef struct opx_self_distance_result {
    uint32_t struct_size;
    int32_t found;           /**< 1: a checked pair within the cutoff; else distance is
                              * the cutoff (+infinity without one, or without pairs) */
    int32_t collided;        /**< 1 when the distance is <= 1e-9 m (the touch rule) */
    uint32_t link_a;         /**< the nearest pair: link_a < link_b, and their shapes */
    uint32_t shape_a;
    uint32_t link_b;
    uint32_t shape_b;
    uint32_t reserved0;
    double distance;         /**< metres, paddings included; >= 0 unless signed */
    double point_on_a[3];    /**< witness on link_a's padded shape, map frame */
    double point_on_b[3];    /**< witness on link_b's; the two are |distance| apart */
    uint64_t link_pairs;     /**< pairs of links measured beyond their bounding boxes */
    uint64_t narrow_tests;   /**< exact distances between convex pieces */
    /** The objects attached to link_a and link_b (linkset.h) whose shapes
     * are the nearest pair, as in opx_self_contact; -1: the link's own. */
    int32_t attached_a;
    int32_t attached_b;
} opx_self_distance_result;

#define OPX_SELF_DISTANCE_RESULT_INIT {sizeof(opx_self_distance_result), 0, 0, 0, 0, 0, 0, 0, \
    0.0, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0, 0, -1, -1}
OPX_API opx_status opx_self_distance_result_init(opx_self_distance_result *result, size_t size);

/**
 * The minimum distance between the link set's checked pairs of links
 * (padding included), with witness points and the two links and shapes.
 * request may be NULL (defaults).
 */
OPX_API opx_status opx_query_self_distance(opx_query *query, const opx_linkset *links,
                                           const opx_self_distance_request *request,
                                           opx_self_distance_result *out_result);

/* ---- Choosing the pairs by sampling ------------------------------------ */

typedef struct opx_pair_sampling_options {
    uint32_t struct_size;
    uint32_t samples;        /**< random configurations (default 10000, as MoveIt's) */
    uint64_t seed;           /**< of the generator (default 1): the same seed, the same pairs */
    /** 1: also disable the pairs that collide in EVERY sample (links meeting
     * at their joint: MoveIt's "Adjacent" and "Always" pairs).  0 (default):
     * only the pairs that never collide. */
    int32_t also_always_colliding;
    /** 1: also disable the pairs that collide at the link set's current
     * poses (MoveIt's "Default" pairs, with the robot at its default
     * configuration).  0 (default): no. */
    int32_t also_colliding_now;
} opx_pair_sampling_options;

#define OPX_PAIR_SAMPLING_OPTIONS_INIT {sizeof(opx_pair_sampling_options), 10000, 1, 0, 0}
OPX_API opx_status opx_pair_sampling_options_init(opx_pair_sampling_options *options, size_t size);

/** How many pairs each rule disabled (a pair counts once, for the first
 * rule in this order that disabled it). */
typedef struct opx_pair_sampling_result {
    uint32_t struct_size;
    uint32_t now;            /**< colliding at the current poses (also_colliding_now) */
    uint32_t never;          /**< colliding in no sample */
    uint32_t always;         /**< colliding in every sample (also_always_colliding) */
} opx_pair_sampling_result;

#define OPX_PAIR_SAMPLING_RESULT_INIT {sizeof(opx_pair_sampling_result), 0, 0, 0}
OPX_API opx_status opx_pair_sampling_result_init(opx_pair_sampling_result *result, size_t size);

/**
 * Disables every pair of links that never collides over `samples` random
 * configurations: each moving joint uniform within its limits (continuous
 * joints, and revolute joints without limits, over [-pi, pi]; prismatic
 * joints without limits stay at 0; mimic joints follow their master), with
 * every link enabled and the current paddings; and, when asked, the pairs
 * colliding now or in every sample, as MoveIt's setup assistant does.
 * Only pairs still enabled are tested; disabled ones stay disabled, and
 * pairs with a link without shapes are left as they are.  The link set's
 * poses and joint positions do not change (a copy is posed).  Sampling can
 * miss a rare colliding configuration: more samples, fewer misses.  The
 * set must come from URDF (else OPX_ERROR_UNSUPPORTED).  options may be
 * NULL (defaults); out_result (may be NULL) gets how many pairs each rule
 * disabled.  Costs about samples x (FK + a self-collision check of the
 * remaining pairs): 0.2 to 2 ms per sample for the PR2.
 */
OPX_API opx_status opx_linkset_disable_never_colliding_pairs(opx_linkset *links,
                                                             const opx_pair_sampling_options *options,
                                                             opx_pair_sampling_result *out_result);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_SELF_COLLISION_H */
