/**
 * Spheres against the map: the robot model sphere-based planners use
 * (VAMP, cuRobo, MoveIt's spherized arms).  Each sphere is answered on its
 * own, exactly as opx_query_collide answers a link set holding that sphere
 * alone (the same touch rule: within 1e-9 m is touching), but without a
 * link set to place: a 5 cm sphere on a 2 cm frame costs 0.07-0.09 us a
 * call, a ninth of a one-sphere opx_query_collide call
 * (docs/performance.md).  The map is read directly, whatever the query's
 * engine, and the query's world is not checked.
 *
 * With unknown space free, the first call after the map changed builds
 * the map's obstacle grid: its obstacle cells as 4x4x4-cell bitmaps,
 * indexed over the box they span (5 bytes a 64 cells of that box, 8 more
 * a brick holding obstacles).  The map keeps it until its next change and
 * every query and thread shares it; it takes about 0.3 ms on a 640x480
 * frame at 2 cm.  Maps whose obstacles span more than 2^30 cells
 * (at 2 cm, a box about 20 m a side), and spheres wider than 60 cells,
 * take a descent of the octree instead, with the same answers.
 *
 * For trajectory optimizers: opx_query_distance_spheres gives each
 * sphere's signed distance, its gradient and a witness (against the map
 * and the query's world), and opx_query_trajectory_cost the obstacle cost
 * of a trajectory of a robot of spheres with its joint gradient.
 */
#ifndef OCTOPROX_SPHERES_H
#define OCTOPROX_SPHERES_H

#include "common.h"
#include "octree.h"
#include "query.h"

#ifdef __cplusplus
extern "C" {
#endif

/** What a sphere check takes as obstacles. */
typedef struct opx_sphere_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< OPX_UNKNOWN_FREE (default) or OPX_UNKNOWN_OCCUPIED */
    double occupancy_threshold; /**< as in opx_collision_request; 0: the octree's */
    int32_t obstacle_geometry;  /**< OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS */
    int32_t reserved0;
} opx_sphere_request;

#define OPX_SPHERE_REQUEST_INIT {sizeof(opx_sphere_request), OPX_UNKNOWN_FREE, 0.0, OPX_OBSTACLE_CELLS, 0}
OPX_API opx_status opx_sphere_request_init(opx_sphere_request *request, size_t size);

/**
 * Checks `count` spheres against the octree, each on its own.  Row i of
 * `spheres` is 4 doubles: the centre x, y, z (map frame, metres) and the
 * radius (>= 0, metres); rows are `stride` bytes apart (0: packed, 32).
 * out_collided[i] gets 1 when sphere i touches an obstacle, else 0;
 * out_collided holds `capacity` elements, and a capacity below count is
 * OPX_ERROR_BUFFER_TOO_SMALL.  A non-finite value or a negative radius is
 * an invalid argument naming the row; count 0 is one too.  request may be
 * NULL (defaults).  On any error the outputs are unspecified.
 */
OPX_API opx_status opx_query_collide_spheres(opx_query *query, const opx_octree *tree, const double *spheres,
                                             size_t count, size_t stride, const opx_sphere_request *request,
                                             uint8_t *out_collided, size_t capacity);

/* ---- Signed distances for optimizers ----------------------------------- */

/** What a sphere distance takes as obstacles, and how far it looks. */
typedef struct opx_sphere_distance_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< OPX_UNKNOWN_FREE (default) or OPX_UNKNOWN_OCCUPIED */
    double occupancy_threshold; /**< as in opx_collision_request; 0: the octree's */
    int32_t obstacle_geometry;  /**< OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS */
    /** 1 (default): the caller's thread; 0: one per hardware thread; as
     * the batch calls (batch.h), from the library's pool. */
    uint32_t max_threads;
    /** Metres, > 0 (default 0.1), +infinity allowed: spheres whose distance
     * is at least this report it, a zero gradient and a NaN witness, and
     * obstacles beyond it are not searched (an activation distance). */
    double max_distance;
} opx_sphere_distance_request;

#define OPX_SPHERE_DISTANCE_REQUEST_INIT \
    {sizeof(opx_sphere_distance_request), OPX_UNKNOWN_FREE, 0.0, OPX_OBSTACLE_CELLS, 1, 0.1}
OPX_API opx_status opx_sphere_distance_request_init(opx_sphere_distance_request *request, size_t size);

/**
 * Signed distances of `count` spheres (rows as in opx_query_collide_spheres:
 * centre x y z in the map frame and radius >= 0, metres, `stride` bytes
 * apart, 0: packed) to the obstacles: the octree's obstacle boxes (each
 * obstacle cell's cube, or with OPX_OBSTACLE_POINT_EXTENTS the box of its
 * sensed points where it keeps one; unknown cubes with
 * OPX_UNKNOWN_OCCUPIED) and the enabled objects of the query's world
 * (opx_query_set_world), all closed sets.  tree may be NULL when the query
 * has a world.
 *
 * Sphere i's distance is sdf(c) - r, c its centre and r its radius, sdf
 * the signed distance field of the union of the obstacles:
 *  - c outside every obstacle: the distance from c to the nearest obstacle
 *    point, the witness;
 *  - c in an obstacle (its surface included): minus the distance from c to
 *    the nearest point outside every obstacle, the witness (the closure of
 *    free space; space beyond the map cube is free).  Exact for the map's
 *    union of cells or extent boxes, however they adjoin: a centre deep in
 *    a wall of cells gets the distance to the wall's nearest free cell.
 *    Where the centre lies both in map obstacles and in world objects, or
 *    in several objects, the depth is the deepest part's: a lower bound of
 *    the union's, exact unless those parts overlap within that depth.
 * Negative distances are penetrations: the sphere leaves every obstacle
 * when its centre moves by -distance along the gradient (while the field
 * stays linear).  A mesh object is a surface, as everywhere.  Distances
 * are exact up to rounding (1e-9 m for world objects, whose touch
 * tolerance is that).
 *
 * The gradient is the unit derivative of the distance with respect to c:
 * (c - witness) / |c - witness| outside, (witness - c) / |witness - c|
 * inside, so it points away from the nearest obstacle (out of it, inside).
 * Where it is not unique: among equidistant obstacle points (or exits) the
 * witness is the first the search meets, the same on every call and for
 * every thread count, and the gradient is that witness's; a centre exactly
 * on the map's obstacle surface gets the normal of the face between the
 * obstacle box holding it and the free space it touches (the normalised
 * sum of the faces' normals at an edge or corner), a centre on an object's
 * surface that object's outward normal.
 *
 * out_distance gets count doubles; out_gradient and out_witness (each may
 * be NULL: not wanted) count rows of 3 doubles, packed.  Each holds
 * `capacity` rows: a capacity below count is OPX_ERROR_BUFFER_TOO_SMALL.
 * A non-finite value or a negative radius is an invalid argument naming
 * the row, count 0 one too; request may be NULL (defaults).  On any error
 * the outputs are unspecified.  With OPX_UNKNOWN_FREE, the first call
 * after the map changed builds its obstacle grid (as the sphere checks do):
 * spheres surely beyond max_distance skip the search, and with whole cells
 * the search reads the grid's bricks around the centre instead of the
 * octree, with the same distances.
 */
OPX_API opx_status opx_query_distance_spheres(opx_query *query, const opx_octree *tree, const double *spheres,
                                              size_t count, size_t stride,
                                              const opx_sphere_distance_request *request, double *out_distance,
                                              double *out_gradient, double *out_witness, size_t capacity);

/* ---- Trajectory cost for optimizers ------------------------------------ */

/** What opx_query_trajectory_cost takes as obstacles, its activation
 * distance and its rows' order. */
typedef struct opx_trajectory_cost_request {
    uint32_t struct_size;
    int32_t unknown_policy;     /**< OPX_UNKNOWN_FREE (default) or OPX_UNKNOWN_OCCUPIED */
    double occupancy_threshold; /**< as in opx_collision_request; 0: the octree's */
    int32_t obstacle_geometry;  /**< OPX_OBSTACLE_CELLS (default) or OPX_OBSTACLE_POINT_EXTENTS */
    /** OPX_JOINTS_BY_COUNT (0, default), OPX_JOINTS_MODEL or
     * OPX_JOINTS_ACTIVE (batch.h): what a row of joint_count values holds. */
    int32_t joint_order;
    /** eps, metres, > 0 and finite (default 0.05): spheres farther than
     * this from every obstacle cost nothing. */
    double activation;
} opx_trajectory_cost_request;

#define OPX_TRAJECTORY_COST_REQUEST_INIT \
    {sizeof(opx_trajectory_cost_request), OPX_UNKNOWN_FREE, 0.0, OPX_OBSTACLE_CELLS, 0, 0.05}
OPX_API opx_status opx_trajectory_cost_request_init(opx_trajectory_cost_request *request, size_t size);

/**
 * The obstacle cost of a trajectory of a robot made of spheres (a link set
 * made from a spherized URDF: every shape of every link, attached objects'
 * too, a sphere; else OPX_ERROR_INVALID_ARGUMENT), and its gradient.
 * `positions` holds waypoint_count rows of joint_count joint values
 * (radians or metres), `stride` bytes apart (0: packed), ordered as
 * request->joint_order says, as opx_query_check_configurations reads them;
 * base_pose (may be NULL: the identity) places the robot's root link in
 * the map frame (x y z qx qy qz qw).  The link set does not move.
 *
 * The cost is the sum over waypoints and enabled spheres of CHOMP's
 * penalty c(d) of the sphere's signed distance d (opx_query_distance_spheres
 * with max_distance = eps = request->activation, against the map and the
 * query's world):
 *   c(d) = -d + eps / 2            for d < 0,
 *   c(d) = (d - eps)^2 / (2 eps)   for 0 <= d < eps,
 *   c(d) = 0                       for d >= eps,
 * continuous with a continuous slope.  out_gradient (may be NULL) gets
 * waypoint_count rows of joint_count doubles, packed, in the rows' order:
 * the derivative of the cost with respect to each joint value, through
 * each sphere's distance gradient and its link's Jacobian (a revolute
 * joint moves a centre c by axis x (c - joint origin), a prismatic one
 * along its axis).  A mimic joint's share goes to the joint it follows,
 * times its multiplier; with OPX_JOINTS_MODEL rows, mimic and fixed
 * joints' entries are 0.  The gradient is exact where the distances are
 * differentiable (spheres.h above: the witness's direction elsewhere).
 * out_gradient holds `capacity` rows: less than waypoint_count is
 * OPX_ERROR_BUFFER_TOO_SMALL.  Self-collision is not part of the cost.
 * Not-finite joint values are invalid arguments naming the row; waypoint
 * count 0 is one too.
 */
OPX_API opx_status opx_query_trajectory_cost(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                             const double *positions, size_t waypoint_count, size_t joint_count,
                                             size_t stride, const opx_pose *base_pose,
                                             const opx_trajectory_cost_request *request, double *out_cost,
                                             double *out_gradient, size_t capacity);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_SPHERES_H */
