/*
 * The scene of the check and export tests: a wall of points 2 m ahead of
 * a sensor at the origin (a map at 0.1 m), and a two-link robot whose
 * "tool" sphere (r 0.1) slides along x on the prismatic joint "slide".
 */
#ifndef OPX_TESTS_CLI_SCENE_H
#define OPX_TESTS_CLI_SCENE_H

#include <octoprox/octoprox.h>

/* Writes wall.pcd, ingests it into wall.bt with the tool and returns the
 * map's path (made once per test program). */
const char *scene_map(void);
/* Writes slider.urdf; returns its path. */
const char *scene_urdf(void);
/* The library's own view: the map and the robot at slide = value. */
opx_octree *scene_load_map(void);
opx_linkset *scene_load_robot(double slide);

#endif /* OPX_TESTS_CLI_SCENE_H */
