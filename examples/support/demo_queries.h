/* The demo's per-waypoint queries with both engines, timed. */
#ifndef OPX_EXAMPLES_DEMO_QUERIES_H
#define OPX_EXAMPLES_DEMO_QUERIES_H

#include <octoprox/octoprox.h>

#define DEMO_ENGINES 2 /* [0] OPX_ENGINE_DIRECT, [1] OPX_ENGINE_AMORTIZED */

typedef struct waypoint_result {
    int collided[DEMO_ENGINES];
    double distance[DEMO_ENGINES];   /* metres */
    double cost[DEMO_ENGINES];       /* m^3 of unknown space overlapped */
    double collide_us[DEMO_ENGINES]; /* microseconds */
    double distance_us[DEMO_ENGINES];
    double cost_us[DEMO_ENGINES];
} waypoint_result;

/* Sets each waypoint's link poses (poses + w * link_count) and runs
 * collision, distance and cost with each engine.  stats gets the amortized
 * context's statistics (its bind times).  0, or -1 after a message. */
int demo_queries_run(const opx_octree *map, opx_linkset *robot, const opx_pose *poses, size_t waypoint_count,
                     size_t link_count, waypoint_result *out, opx_query_stats *stats);

/* The centres and sizes of every cell the robot touches at its current
 * poses (malloc'd, appended to *centers / *sizes, *count grows). */
int demo_colliding_cells(const opx_octree *map, const opx_linkset *robot, double **centers, double **sizes,
                         size_t *count);

double demo_now_us(void);

#endif /* OPX_EXAMPLES_DEMO_QUERIES_H */
