/* The demo's per-waypoint queries with both engines, timed. */
#ifndef OPX_EXAMPLES_DEMO_QUERIES_H
#define OPX_EXAMPLES_DEMO_QUERIES_H

#include <octoprox/octoprox.h>

#define DEMO_ENGINES 2 /* [0] OPX_ENGINE_DIRECT, [1] OPX_ENGINE_AMORTIZED */

typedef struct waypoint_result {
    int collided[DEMO_ENGINES];      /* with the map or a known object */
    double distance[DEMO_ENGINES];   /* metres, to the map and the known objects */
    int32_t nearest_object[DEMO_ENGINES]; /* the nearest known object, -1: a cell */
    int hits_map, hits_objects;      /* which of the two the robot touches */
    double cost[DEMO_ENGINES];       /* m^3 of unknown space overlapped */
    double collide_us[DEMO_ENGINES]; /* microseconds */
    double distance_us[DEMO_ENGINES];
    double cost_us[DEMO_ENGINES];
} waypoint_result;

/* Sets each waypoint's link poses (poses + w * link_count) and runs
 * collision, distance and cost with each engine, the known objects of
 * `world` (may be NULL) checked beside the map; then, untimed, which of
 * the two the robot touches.  stats gets the amortized context's
 * statistics (its bind times).  0, or -1 after a message. */
int demo_queries_run(const opx_octree *map, const opx_world *world, opx_linkset *robot, const opx_pose *poses,
                     size_t waypoint_count, size_t link_count, waypoint_result *out, opx_query_stats *stats);

/* The centres and sizes of every cell the robot touches at its current
 * poses (malloc'd, appended to *centers / *sizes, *count grows). */
int demo_colliding_cells(const opx_octree *map, const opx_linkset *robot, double **centers, double **sizes,
                         size_t *count);

double demo_now_us(void);

#endif /* OPX_EXAMPLES_DEMO_QUERIES_H */
