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

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_SPHERES_H */
