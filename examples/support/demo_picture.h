/*
 * The demo's picture, in the manner of paper Fig. 3: a slice of the map
 * (occupied, free, unknown in distinct colours), the robot at a few
 * waypoints of its path (silhouettes projected onto the slice plane), the
 * known objects beside the map (their silhouettes, hatched), the cells and
 * objects it collides with, and the boxes of unknown space the path sweeps
 * through (their cost), with a legend, axes and a scale bar in metres.
 */
#ifndef OPX_EXAMPLES_DEMO_PICTURE_H
#define OPX_EXAMPLES_DEMO_PICTURE_H

#include "mesh_out.h"

#include <octoprox/octoprox.h>

/* The slice plane: the points origin + a * u + b * v (map frame, u and v
 * orthonormal), drawn for a in [u_min, u_max], b in [v_min, v_max]. */
typedef struct picture_view {
    double origin[3], u[3], v[3];
    double u_min, u_max, v_min, v_max;
    double pixels_per_metre;
    const char *title;
    const char *u_name, *v_name; /* axis names, e.g. "X" */
} picture_view;

#define PICTURE_MAX_ARMS 8

typedef struct picture_input {
    const opx_octree *map;
    picture_view view;
    /* The sensor and the edges of its field of view in the plane (map
     * frame; direction count 0..2). */
    double sensor[3];
    double fov_edges[2][3];
    int fov_edge_count;
    /* The robot's parts that do not move (may be NULL), drawn in a colour
     * of their own, and their legend label (NULL: "ROBOT BODY (STILL)"). */
    const mesh_out *body;
    const char *body_label;
    /* Robot silhouettes (map-frame triangles) and their labels. */
    const mesh_out *arms[PICTURE_MAX_ARMS];
    const char *arm_labels[PICTURE_MAX_ARMS];
    int arm_collides[PICTURE_MAX_ARMS];
    int arm_count;
    /* Nonzero: the arms as outlines alone, the cells under them in their
     * own colours (a picture about the cells the robot covers). */
    int arms_outline_only;
    /* The tool's path (optional): its map-frame position at each of
     * tool_path_count waypoints (3 each), tool_collides[w] nonzero where
     * waypoint w collides, the waypoint each arm shows, a legend label. */
    const double *tool_path;
    const unsigned char *tool_collides;
    size_t tool_path_count;
    size_t arm_waypoints[PICTURE_MAX_ARMS];
    const char *tool_label;
    /* Cells hit at colliding waypoints: centres (3 each) and edges. */
    const double *colliding_centers;
    const double *colliding_sizes;
    size_t colliding_count;
    /* Known objects (world.h; may be NULL), drawn hatched in a colour of
     * their own with their legend label, and the points where the robot
     * touches them (3 each). */
    const mesh_out *known;
    const char *known_label;
    const double *object_contacts;
    size_t object_contact_count;
    /* Unknown-space cost boxes of the path. */
    const opx_cost_box *cost_boxes;
    size_t cost_box_count;
    double total_cost;
    /* Labels placed in the map (map frame; drawn at their projection). */
    const char *notes[8];
    double note_at[8][3];
    int note_count;
} picture_input;

/* Renders and writes a PNG; 0, or -1 (out of memory, file not written). */
int demo_picture_write(const picture_input *in, const char *path);

/* A before/after pair: two panels side by side, each a picture_input
 * drawn as above (its view's title over it, no legend), under one title,
 * and one short legend (the cell classes, the left panel's first arm and
 * its label, the camera's field of view).  0, or -1 as above. */
int demo_picture_write_pair(const picture_input *left, const picture_input *right, const char *title,
                            const char *path);

#endif /* OPX_EXAMPLES_DEMO_PICTURE_H */
