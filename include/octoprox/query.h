/*
 * opx_query: a per-thread query context.  It holds the engine, its scratch
 * memory and the results of its last query, so repeated queries allocate
 * nothing once warm.  Use one context per thread; any number of contexts
 * may query the same octree and link set at once (both are read-only
 * during queries).
 */
#ifndef OCTOPROX_QUERY_H
#define OCTOPROX_QUERY_H

#include "common.h"
#include "linkset.h"
#include "octree.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct opx_query opx_query;

/** Direct octree traversal (paper IV.B): no per-frame preprocessing. */
#define OPX_ENGINE_DIRECT 1
/** Amortized (paper IV.A): the first query on an octree frame turns its
 * obstacle cells into boxes in a Morton-built tree held by the context
 * (rebuilt when the octree changes or the threshold differs); every query
 * then refines the trees it used a little.  Collision, distance, cost and
 * paths (every option: OPX_UNKNOWN_OCCUPIED, compute_cost,
 * compute_penetration, signed_distance) run on the context's trees with
 * the same exact tests, so answers equal the direct engine's.  The first
 * query that needs them also builds, once per frame, a tree of the unknown
 * cubes (OPX_UNKNOWN_OCCUPIED, or cost) and one of the uncertain cells
 * (cost); plain collision and distance never pay for them.  Where several
 * answers are equally valid (which contacts are kept when more than
 * max_contacts exist; which cell gives the witness points at distance 0),
 * the pick follows the tree as earlier queries refined it, so a used
 * context and a fresh one may return different, equally correct contacts
 * or witnesses; collided, distances, costs and counts are the same. */
#define OPX_ENGINE_AMORTIZED 2

typedef struct opx_query_options {
    uint32_t struct_size;
    int32_t engine;        /**< OPX_ENGINE_DIRECT (default) or OPX_ENGINE_AMORTIZED */
    uint32_t refine_steps; /**< amortized: refinement paths per query (default 1) */
    uint32_t morton_bits;  /**< amortized: lattice bits per axis, 1..21 (default 10) */
} opx_query_options;

#define OPX_QUERY_OPTIONS_INIT {sizeof(opx_query_options), OPX_ENGINE_DIRECT, 1, 10}
OPX_API opx_status opx_query_options_init(opx_query_options *options, size_t size);

/** options may be NULL (defaults). */
OPX_API opx_status opx_query_create(const opx_query_options *options, opx_query **out);
OPX_API void opx_query_destroy(opx_query *query);

/** What a context holds (amortized engine; zeros for the direct engine). */
typedef struct opx_query_stats {
    uint32_t struct_size;
    int32_t engine;
    uint64_t boxes;             /**< obstacle boxes in the bound tree (not the unknown or uncertain ones) */
    /** Trees built: one per octree frame (or threshold) bound, plus, once per
     * frame, the unknown-cube tree and the uncertain-cell tree (per
     * threshold) when a query first needs them. */
    uint64_t builds;
    uint64_t refine_steps_done; /**< on the obstacle tree, since its last build */
    /** Surface-area cost of the tree over that of a top-down median-split
     * tree on the same boxes (that tree's cost is computed on the first
     * request after a build: O(n log n)); 1 when empty. */
    double sah_ratio;           /**< of the obstacle tree */
    double extract_ms;          /**< last bind: obstacle cells to boxes (paper T_{1,1}) */
    double build_ms;            /**< last bind: boxes to the obstacle tree (paper ~T_{1,2}) */
} opx_query_stats;

#define OPX_QUERY_STATS_INIT {sizeof(opx_query_stats), 0, 0, 0, 0, 0.0, 0.0, 0.0}
OPX_API opx_status opx_query_stats_init(opx_query_stats *stats, size_t size);
OPX_API opx_status opx_query_get_stats(const opx_query *query, opx_query_stats *out_stats);

/* What unknown (never observed) space is during a query.  Only the map
 * cube (+-32768 x resolution on each axis) is searched: space outside it
 * is neither an obstacle nor reported, whatever the policy. */
#define OPX_UNKNOWN_FREE 0     /**< optimistic, as MoveIt/FCL (default) */
#define OPX_UNKNOWN_OCCUPIED 1 /**< safe: a link must lie in observed space */

/* What an occupied cell is as an obstacle (docs/geometry.md).  Uncertain
 * and unknown space are whole cubes in both models (cost, and unknown
 * space under OPX_UNKNOWN_OCCUPIED). */
#define OPX_OBSTACLE_CELLS 0 /**< its whole cube, as FCL and MoveIt (default) */
/** The box of the sensed points that made it occupied, where the map
 * recorded one (cells hit by opx_octree_insert_points or a depth image);
 * a cell without one (read from a file or a message) is its whole cube. */
#define OPX_OBSTACLE_POINT_EXTENTS 1

typedef struct opx_collision_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< OPX_UNKNOWN_FREE (default) or OPX_UNKNOWN_OCCUPIED */
    /** Cells with probability >= this are obstacles.  0 (default): the
     * octree's occupied_threshold. */
    double occupancy_threshold;
    /** 0: answer yes/no only; 1 (default): stop at the first contact and
     * report it; N: collect up to N contacts (UINT32_MAX: all). */
    uint32_t max_contacts;
    /** 1: also the cost of uncertain and unknown space (paper IV.C): boxes
     * where links overlap cells that are neither known free nor obstacles
     * (uncertain: octree free_threshold <= p < occupancy threshold), and
     * unknown space inside the region below.  Each box is a cell
     * intersected with the link's bounding box, one per (link, cell); its
     * cost is probability x volume.  Obstacles hit are still contacts. */
    int32_t compute_cost;
    uint32_t max_cost_boxes;    /**< the costliest boxes kept (default 16) */
    uint32_t reserved0;
    double unknown_probability; /**< probability given to unknown space (0.5) */
    /** Where unknown space counts (map frame).  When region_min is not below
     * region_max on every axis (the default zeros): the bounds of the
     * observed cells. */
    double region_min[3];
    double region_max[3];
    /** 1: each contact also gets its penetration depth, normal and point
     * (exact for polytopes: EPA on the Minkowski difference). */
    int32_t compute_penetration;
    int32_t obstacle_geometry;  /**< OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS */
} opx_collision_request;

#define OPX_COLLISION_REQUEST_INIT \
    {sizeof(opx_collision_request), OPX_UNKNOWN_FREE, 0.0, 1, 0, 16, 0, 0.5, \
     {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0, OPX_OBSTACLE_CELLS}
OPX_API opx_status opx_collision_request_init(opx_collision_request *request, size_t size);

typedef struct opx_collision_result {
    uint32_t struct_size;
    int32_t collided;       /**< 1 when some enabled link touches an obstacle cell */
    uint64_t contact_count; /**< contacts held by the query (opx_query_get_contact) */
    /** 1 when a contact beyond the first max_contacts was found and left
     * out.  With max_contacts 0 or 1 the search stops at the first contact,
     * so truncated stays 0 although more contacts may exist. */
    int32_t truncated;
    uint32_t reserved0;
    uint64_t narrow_tests;  /**< exact shape-vs-cell tests run (a cost measure) */
    double total_cost;      /**< sum of probability x volume over ALL cost boxes (m^3) */
    uint64_t cost_box_count; /**< boxes held by the query (opx_query_get_cost_box) */
    uint64_t cost_boxes_found; /**< all boxes; the held ones are the costliest */
} opx_collision_result;

#define OPX_COLLISION_RESULT_INIT {sizeof(opx_collision_result), 0, 0, 0, 0, 0, 0.0, 0, 0}
OPX_API opx_status opx_collision_result_init(opx_collision_result *result, size_t size);

/** One contact: a shape of a link touching an obstacle cell.  Cells are
 * cubes in the map frame; a shape touching a cell (distance <= padding,
 * closed sets) collides; see docs/geometry.md for the tolerance. */
typedef struct opx_contact {
    uint32_t struct_size;
    uint32_t link;          /**< index in the link set */
    uint32_t shape;         /**< index within the link */
    int32_t cell_class;     /**< the cell's class in the octree (OPX_CELL_OCCUPIED;
                             * uncertain or free when the request's threshold is
                             * below the octree's; OPX_CELL_UNKNOWN with
                             * OPX_UNKNOWN_OCCUPIED) */
    double cell_center[3];  /**< map frame, metres */
    double cell_size;       /**< edge, metres */
    double cell_probability; /**< 0.5 for unknown cells */
    /** With compute_penetration (else zeros): how deep the padded shape is
     * in the cell (metres, >= 0; 0 when only touching), the unit direction
     * it went in (moving the link by -depth * normal separates the pair),
     * and the contact point: midway between the shape's deepest point and
     * where it leaves the cell, map frame. */
    double depth;
    double normal[3];
    double position[3];
    /** The world object touched (world.h: its index), or -1 for an octree
     * cell.  For an object the cell fields above are zeros. */
    int32_t object;
    uint32_t object_shape;  /**< the object's shape touched (0 for a cell) */
    /** The object attached to the link (linkset.h, opx_linkset_attach_object:
     * its index) whose shape touched, `shape` then being the shape's index
     * within that object; -1: one of the link's own shapes. */
    int32_t attached;
    uint32_t reserved1;     /**< padding; 0 */
} opx_contact;

#define OPX_CONTACT_INIT {sizeof(opx_contact), 0, 0, 0, {0.0, 0.0, 0.0}, 0.0, 0.0, 0.0, \
    {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, -1, 0, -1, 0}
OPX_API opx_status opx_contact_init(opx_contact *contact, size_t size);

/** A box of uncertain or unknown space overlapped by a link. */
typedef struct opx_cost_box {
    uint32_t struct_size;
    uint32_t link;
    int32_t cell_class;     /**< OPX_CELL_UNCERTAIN or OPX_CELL_UNKNOWN */
    uint32_t reserved0;
    double min[3];          /**< the box, map frame, metres */
    double max[3];
    double probability;     /**< the cell's (unknown: the request's) */
    double cost;            /**< probability x volume, m^3 */
    double cell_center[3];  /**< the whole cell the box lies in */
    double cell_size;
} opx_cost_box;

#define OPX_COST_BOX_INIT {sizeof(opx_cost_box), 0, 0, 0, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, \
    0.0, 0.0, {0.0, 0.0, 0.0}, 0.0}
OPX_API opx_status opx_cost_box_init(opx_cost_box *box, size_t size);

/**
 * Does the link set (enabled links, padding included, at their current
 * poses) collide with the octree?  request may be NULL (defaults).  The
 * contacts and cost boxes stay in the query until its next collision or
 * path query (a path query holds no contacts).
 */
OPX_API opx_status opx_query_collide(opx_query *query, const opx_octree *tree,
                                     const opx_linkset *links,
                                     const opx_collision_request *request,
                                     opx_collision_result *out_result);

/** Contact `index` (< contact_count) of the last collision query. */
OPX_API opx_status opx_query_get_contact(const opx_query *query, size_t index,
                                         opx_contact *out_contact);
/** Cost box `index` (< cost_box_count) of the last collision query,
 * costliest first. */
OPX_API opx_status opx_query_get_cost_box(const opx_query *query, size_t index,
                                          opx_cost_box *out_box);

/* ---- Distance ---------------------------------------------------------- */

typedef struct opx_distance_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< OPX_UNKNOWN_FREE (default) or OPX_UNKNOWN_OCCUPIED */
    double occupancy_threshold; /**< as in opx_collision_request; 0: the octree's */
    /** Allowed error: the reported distance exceeds the true minimum by at
     * most max(abs_err, rel_err * distance).  0 and 0 (default): exact. */
    double abs_err;
    double rel_err;
    /** Obstacles farther than this (metres) are not searched: the result is
     * then found = 0, distance = cutoff ("at least cutoff").  0 (default)
     * or +infinity: no cutoff. */
    double cutoff;
    int32_t per_link;        /**< 1: also each link's minimum (opx_query_get_link_distances) */
    /** 1: when links overlap obstacles, the distance is minus the deepest
     * penetration (the padded shape's depth into a cell, by EPA), with the
     * witnesses at the deepest point of the link and where it leaves the
     * cell (they are -distance apart).  0 (default): overlap is distance 0. */
    int32_t signed_distance;
    /** OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS; with
     * extents the witness on the cell lies on the cell's point box. */
    int32_t obstacle_geometry;
    int32_t reserved0;
} opx_distance_request;

#define OPX_DISTANCE_REQUEST_INIT \
    {sizeof(opx_distance_request), OPX_UNKNOWN_FREE, 0.0, 0.0, 0.0, 0.0, 0, 0, \
     OPX_OBSTACLE_CELLS, 0}
OPX_API opx_status opx_distance_request_init(opx_distance_request *request, size_t size);

typedef struct opx_distance_result {
    uint32_t struct_size;
    int32_t found;          /**< 1: an obstacle within the cutoff; else distance
                             * is the cutoff (or +infinity without one) */
    int32_t collided;       /**< 1 when the distance is <= 1e-9 m, the touch rule of
                             * collision queries (touching or overlapping) */
    int32_t cell_class;     /**< class of the closest cell (OPX_CELL_UNKNOWN for
                             * unknown space with OPX_UNKNOWN_OCCUPIED) */
    uint32_t link;          /**< the closest link and its shape */
    uint32_t shape;
    double distance;        /**< metres, padding included; >= 0 unless signed */
    double point_on_link[3]; /**< witness on the padded shape, map frame */
    double point_on_cell[3]; /**< witness on the cell, map frame; the two are
                              * `distance` apart */
    double cell_center[3];  /**< the closest cell, map frame */
    double cell_size;
    double cell_probability; /**< 0.5 for unknown cells */
    uint64_t narrow_tests;  /**< exact shape-vs-cell distances computed */
    /** The nearest world object (world.h: its index; point_on_cell then
     * lies on it and the cell fields are zeros), or -1 for a cell. */
    int32_t object;
    uint32_t object_shape;  /**< the object's nearest shape (0 for a cell) */
    /** The object attached to `link` (linkset.h: its index) whose shape is
     * the nearest, `shape` then being its index within that object; -1:
     * one of the link's own shapes. */
    int32_t attached;
    uint32_t reserved0;     /**< padding; 0 */
} opx_distance_result;

#define OPX_DISTANCE_RESULT_INIT {sizeof(opx_distance_result), 0, 0, 0, 0, 0, 0.0, \
    {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.0, 0.0, 0, -1, 0, -1, 0}
OPX_API opx_status opx_distance_result_init(opx_distance_result *result, size_t size);

/**
 * Minimum distance between the enabled links (padding included) and the
 * obstacle cells, with witness points.  request may be NULL (defaults).
 */
OPX_API opx_status opx_query_distance(opx_query *query, const opx_octree *tree,
                                      const opx_linkset *links,
                                      const opx_distance_request *request,
                                      opx_distance_result *out_result);

/**
 * Each link's minimum distance from the last distance query, in link order
 * (none, *out_count = 0, unless that query had per_link = 1) (+infinity: disabled, or nothing within the
 * cutoff).  *out_count gets the number of links; OPX_ERROR_BUFFER_TOO_SMALL
 * when capacity is smaller (the first `capacity` are written).
 */
OPX_API opx_status opx_query_get_link_distances(const opx_query *query, double *out_distances,
                                                size_t capacity, size_t *out_count);

/* ---- Paths ------------------------------------------------------------- */

typedef struct opx_path_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< as in opx_collision_request */
    double occupancy_threshold; /**< as in opx_collision_request; 0: the octree's */
    int32_t compute_distance;   /**< 1: the minimum (unsigned) distance along the path */
    /** 1: the cost of uncertain and unknown space the path sweeps through
     * (paper Fig. 3), each cell counted once: a cell's box is the bounding
     * box of the boxes (cell x link bounding box) of every waypoint and link
     * that touches it.  Other fields as in opx_collision_request. */
    int32_t compute_cost;
    uint32_t max_cost_boxes;    /**< the costliest boxes kept (default 16) */
    int32_t obstacle_geometry;  /**< OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS */
    double unknown_probability; /**< 0.5 */
    double region_min[3];
    double region_max[3];
} opx_path_request;

#define OPX_PATH_REQUEST_INIT {sizeof(opx_path_request), OPX_UNKNOWN_FREE, 0.0, 0, 0, 16, OPX_OBSTACLE_CELLS, \
    0.5, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}}
OPX_API opx_status opx_path_request_init(opx_path_request *request, size_t size);

typedef struct opx_path_result {
    uint32_t struct_size;
    int32_t collided;                 /**< 1: some waypoint collides */
    int64_t first_colliding_waypoint; /**< -1: none */
    double min_distance;              /**< with compute_distance; +infinity otherwise
                                       * or when the map holds no obstacle */
    int64_t min_distance_waypoint;    /**< -1: none */
    double total_cost;                /**< m^3, over all cells swept */
    uint64_t cost_box_count;          /**< held by the query (opx_query_get_cost_box) */
    uint64_t cost_boxes_found;        /**< all cells swept */
    uint64_t narrow_tests;
} opx_path_result;

#define OPX_PATH_RESULT_INIT {sizeof(opx_path_result), 0, -1, 0.0, -1, 0.0, 0, 0, 0}
OPX_API opx_status opx_path_result_init(opx_path_result *result, size_t size);

/**
 * Checks a path of `waypoint_count` waypoints in order.  Waypoint w gives
 * one pose per link (map frame): link l's pose is at
 *   (const char *)poses + w * waypoint_stride + l * pose_stride
 * (pose_stride 0: sizeof(opx_pose); waypoint_stride 0: links x pose_stride).
 * The link set itself is not moved.  Without distance or cost the check
 * stops at the first colliding waypoint.  request may be NULL (defaults).
 * On a query with a world (world.h) each waypoint is also checked against
 * its objects, which add no cost; tree may then be NULL (no compute_cost).
 */
OPX_API opx_status opx_query_path(opx_query *query, const opx_octree *tree,
                                  const opx_linkset *links, const opx_pose *poses,
                                  size_t waypoint_count, size_t pose_stride,
                                  size_t waypoint_stride, const opx_path_request *request,
                                  opx_path_result *out_result);

/**
 * A caller's boxes as the map (a "collision map" from another source:
 * paper IV.A accepts any set of boxes).  `boxes` holds count axis-aligned
 * boxes of 6 doubles each, min x y z then max x y z (map frame, metres,
 * min <= max), `stride` bytes apart (0: packed, 48 bytes).  The context must
 * be OPX_ENGINE_AMORTIZED: it copies the boxes and builds its Morton tree
 * over them (opx_query_get_stats: extract_ms is the copy, build_ms the
 * tree), refined by every query as for octrees.  The boxes stay bound until
 * the next opx_query_bind_boxes, or until an octree query binds its frame.
 * count 0 binds an empty map.
 */
OPX_API opx_status opx_query_bind_boxes(opx_query *query, const double *boxes, size_t count, size_t stride);
/**
 * Collision and distance against the bound boxes, with the octree queries'
 * exact tests, results and rules (max_contacts, cutoff, per_link).  A box
 * is reported as a cell: cell_center its centre, cell_size its LONGEST edge,
 * class OPX_CELL_OCCUPIED, probability 1.  compute_penetration and
 * signed_distance work as for octrees (the depth of a shape into a box).
 * occupancy_threshold and unknown_policy do not apply (they are only
 * checked); compute_cost is an error (boxes have no uncertain or unknown
 * space).  Without bound boxes: OPX_ERROR_INVALID_ARGUMENT.
 */
OPX_API opx_status opx_query_collide_boxes(opx_query *query, const opx_linkset *links,
                                           const opx_collision_request *request,
                                           opx_collision_result *out_result);
OPX_API opx_status opx_query_distance_boxes(opx_query *query, const opx_linkset *links,
                                            const opx_distance_request *request,
                                            opx_distance_result *out_result);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_QUERY_H */
