/* Printing what `octoprox check` found, as text or JSON. */
#ifndef OPX_TOOLS_CHECK_REPORT_H
#define OPX_TOOLS_CHECK_REPORT_H

#include "cli.h"
#include "robot_args.h"

#define CHECK_MAX_LISTED 10 /* contacts and cost boxes listed */

typedef struct check_context {
    const char *map_path, *urdf_path, *path_file;  /* map_path NULL: --self or --scene without a map */
    const char *scene_path;                        /* --scene: NULL when not given */
    const opx_world *world;                        /* its objects (NULL without --scene) */
    const robot_args *robot;
    const opx_octree *map;
    const opx_linkset *links;
    opx_query *query;
    int32_t unknown_policy;
    int32_t obstacle_geometry; /* OPX_OBSTACLE_CELLS or OPX_OBSTACLE_POINT_EXTENTS */
    int want_distance, want_cost, want_self, json;
    double resolution; /* --path: joint step between checked configurations (rad or m) */
    uint32_t threads;  /* --path: threads of the batch calls (0: every core) */
    int certified;     /* --path --certified: every configuration of each motion (OPX_MOTION_CERTIFIED) */
} check_context;

/* The motions between the waypoints of a path (--path). */
typedef struct check_motions_report {
    size_t count;             /* waypoints - 1 */
    int64_t first_colliding;  /* motion i goes from waypoint i to i + 1; -1: none */
    double first_fraction;    /* along that motion, in [0, 1]; -1: none */
} check_motions_report;

const char *check_class_name(int32_t cell_class);
const char *check_link_name(const opx_linkset *links, uint32_t link);

/* The head of the report (map or none, robot, its padding, disabled links
 * and SRDF, policy); JSON: opens the object. */
void check_print_head(const check_context *c);
/* Contacts of the last collision query: count, colliding links, a few. */
void check_print_contacts(const check_context *c, const opx_collision_result *r);
/* Cost boxes held by the query (after collide or path with cost). */
void check_print_cost(const check_context *c, double total, uint64_t found, uint64_t held);
void check_print_distance(const check_context *c, const opx_distance_result *d);
void check_print_path(const check_context *c, size_t waypoints, const opx_path_result *r);
void check_print_motions(const check_context *c, const check_motions_report *m);
/* The tail: the verdict, the time; JSON: closes the object. */
void check_print_tail(const check_context *c, int collided, double query_ms);

#endif /* OPX_TOOLS_CHECK_REPORT_H */
