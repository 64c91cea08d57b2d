/* Robot shapes as triangles in the map frame, for export and pictures. */
#ifndef OPX_TOOLS_SHAPE_MESH_H
#define OPX_TOOLS_SHAPE_MESH_H

#include "mesh_out.h"

#include <octoprox/octoprox.h>

/* Appends the triangles of `shape` (in its link frame) placed at link_pose
 * (map frame) to group `group`.  Spheres, cylinders and capsules are
 * tessellated; a convex shape is its hull (its bounding box beyond 64
 * vertices); a mesh is its own triangles. */
void shape_to_mesh(const opx_shape *shape, const opx_pose *link_pose, mesh_out *mesh, uint32_t group);

/* Appends every shape of every link of `links` at its current pose;
 * link l goes to group groups[l] (UINT32_MAX: the link is left out). */
int linkset_to_mesh(const opx_linkset *links, mesh_out *mesh, const uint32_t *groups);

/* Pose helpers: a vector rotated by a unit quaternion (x y z w), out = a * b,
 * and a point mapped by a pose. */
void pose_rotate(const double q[4], const double v[3], double out[3]);
void pose_compose(const opx_pose *a, const opx_pose *b, opx_pose *out);
void pose_apply(const opx_pose *pose, const double in[3], double out[3]);

#endif /* OPX_TOOLS_SHAPE_MESH_H */
