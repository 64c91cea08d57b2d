/*
 * The demo's self-filter step: a robot's camera sees the robot.  The
 * robot's checked links, at the configuration the frame is captured in,
 * are rendered exactly into the camera's organized frame (the nearer of
 * the robot and the scene on each pixel), and the composite is ingested
 * twice into fresh maps: once as it is, once with the robot as the
 * insert's self-filter (opx_insert_options: robot, robot_padding,
 * clear_robot_volume).  The report gives the insert report's counts and a
 * collision check of the robot against each map; the picture shows both
 * maps side by side, a slice through the robot.
 */
#ifndef OPX_EXAMPLES_DEMO_SELF_FILTER_H
#define OPX_EXAMPLES_DEMO_SELF_FILTER_H

#include "demo_picture.h"
#include "depth_render.h"

#include <octoprox/octoprox.h>
#include <octoprox/robot.h>

typedef struct self_filter_scene {
    /* The robot: loaded, its still joints set, only the links to filter
     * and check enabled (disabled links are neither drawn into the frame
     * nor filtered); is_robot_link names the same links. */
    opx_linkset *robot;
    int (*is_robot_link)(const char *name);
    opx_pose base_pose;
    /* The configuration at capture time. */
    const char *const *joint_names;
    const double *positions;
    size_t joint_count;
    const char *pose_label; /* what the report calls it */
    /* The frame: an organized cloud in the camera's optical frame
     * (camera.width * camera.height points, NaN: no return), and the
     * camera (its pose in the map frame). */
    const float *points;
    depth_camera camera;
    double resolution, robot_padding;
    /* The picture: the slice through the robot (title unused: each panel
     * gets its own), the camera's field of view in it, the robot's label. */
    picture_view view;
    double fov_edges[2][3];
    const char *robot_label;
    const char *out_dir, *picture_name;
} self_filter_scene;

/* Runs and prints the step, writes the picture; 0, or -1 after a message. */
int demo_self_filter_run(const self_filter_scene *scene);

#endif /* OPX_EXAMPLES_DEMO_SELF_FILTER_H */
