/*
 * The demo's known objects (world.h): a MoveIt scene as .scene text,
 * written into the output folder and read back into a world, as a robot
 * reads the scene its planner exports; the objects as triangles for the
 * picture, and the points where the robot touches them.
 */
#ifndef OPX_EXAMPLES_DEMO_WORLD_H
#define OPX_EXAMPLES_DEMO_WORLD_H

#include "mesh_out.h"

#include <octoprox/octoprox.h>

#include <stddef.h>

/* Writes `text` to out_dir/name (its path into path) and reads it with
 * opx_world_load_scene_file.  0, or -1 after a message. */
int demo_world_load(const char *out_dir, const char *name, const char *text, char *path, size_t path_size,
                    opx_world **out);

/* "1 object (table: 5 shapes)" for the report. */
void demo_world_describe(const opx_world *world, char *text, size_t size);

/* Every shape of every enabled object as triangles in the map frame, in
 * one group. */
void demo_world_mesh(const opx_world *world, mesh_out *mesh);

/* Appends the points (map frame, 3 each) where the robot, at its current
 * poses, touches the world's objects (the shape pairs' contact points). */
int demo_world_contacts(const opx_world *world, const opx_linkset *robot, double **points, size_t *count);

#endif /* OPX_EXAMPLES_DEMO_WORLD_H */
