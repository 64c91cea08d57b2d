/*
 * Reading a map that a fuzz input made, every way the API offers, with the
 * checks the documentation allows: leaf counts agree with the statistics,
 * a leaf's centre classifies as that leaf, a saved image loads back (a full
 * image with the same leaves), and collision and distance queries on both
 * engines agree.
 */
#ifndef OPX_FUZZ_TREE_H
#define OPX_FUZZ_TREE_H

#include <octoprox/octoprox.h>

/* After a load that gave `status` and `tree`: a failure must hand out no
 * tree (NULL); a loaded tree is exercised, then destroyed. */
void fuzz_check_loaded(opx_status status, opx_octree *tree);

/* Runs the reads and checks on tree (which stays unchanged). */
void fuzz_exercise_tree(const opx_octree *tree);

/* Collision and distance of a sphere of `radius` at `center` on both
 * engines; aborts when the engines disagree. */
void fuzz_query_sphere(const opx_octree *tree, const double center[3], double radius);

#endif /* OPX_FUZZ_TREE_H */
