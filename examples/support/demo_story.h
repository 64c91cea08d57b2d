/*
 * The demo's story, the same for the built-in room and the real data: a
 * sensor frame is ingested into a map; known objects, when given, are read
 * from a MoveIt scene; a robot follows a straight-line path in joint
 * space; every waypoint is checked for collision and distance (the map and
 * the known objects) and the cost of unknown space with both engines
 * (timed); one path query sums the swept cost; a picture shows it all.
 */
#ifndef OPX_EXAMPLES_DEMO_STORY_H
#define OPX_EXAMPLES_DEMO_STORY_H

#include "demo_picture.h"

#include <octoprox/octoprox.h>
#include <octoprox/robot.h>

#define STORY_MAX_JOINTS 16

typedef struct demo_story {
    /* The sensor frame: points in the sensor frame, and its pose. */
    const char *frame_label;
    const float *points;
    size_t point_count;
    opx_pose sensor_pose;
    double resolution;
    /* The robot (loaded, links not to check already disabled) and its path. */
    const char *robot_label;
    opx_linkset *robot;
    opx_pose base_pose;
    const char *joint_names[STORY_MAX_JOINTS];
    double start[STORY_MAX_JOINTS], goal[STORY_MAX_JOINTS];
    size_t joint_count;
    size_t waypoint_count;
    /* Links that do not move along the path (drawn once); NULL:
     * every link moves. */
    int (*is_body_link)(const char *name);
    /* The link whose path the picture draws, a dot a waypoint (NULL: none). */
    const char *tool_link;
    /* Known objects beside the map (NULL: none): a MoveIt scene as .scene
     * text, written to out_dir/scene_name and read back into a world, and
     * what the report calls them ("table"). */
    const char *scene_name, *scene_text, *known_name;
    /* What the picture shows (map is filled in by the story). */
    picture_input picture;
    const char *out_dir, *picture_name, *map_name;
} demo_story;

/* Runs and prints the story, writes the picture and the map; returns 0, or
 * -1 after printing why it failed. */
int demo_story_run(demo_story *story);

#endif /* OPX_EXAMPLES_DEMO_STORY_H */
