// MoveIt planning scenes as YAML (rostopic echo, ros2 topic echo, or a
// dump of moveit_msgs/PlanningScene), and robowflex's dialect of them
// (MotionBenchMaker's benchmark scenes): world.collision_objects[] (or a
// PlanningSceneWorld's collision_objects[]), each applied in file order
// (scene_update.hpp).  Several documents ("---") apply one after the
// other; one that is not a diff (is_diff false or absent) first clears
// the world.  Per object:
//   id, operation (0 ADD, 1 REMOVE, 2 APPEND, 3 MOVE, or the words, any
//                       case; default ADD)
//   header.frame_id     a child frame of fixed_frame_transforms[] places
//                       the object; any other is taken as the map frame
//   pose                the object in that frame (absent: identity)
//   primitives[]        type 1 BOX [x y z], 2 SPHERE [radius],
//                       3 CYLINDER [height, radius] (or box, sphere,
//                       cylinder); 4 CONE and other kinds are refused
//                       (OPX_ERROR_UNSUPPORTED)
//   primitive_poses[]   per primitive, in the object frame (missing ones:
//                       identity, as MoveIt)
//   meshes[]            vertices[], triangles[] (.vertex_indices or bare);
//                       mesh files (resource) are refused
//   mesh_poses[]        per mesh
//   planes[]            refused when not empty (infinite planes)
// Points are maps {x, y, z} or lists [x, y, z], quaternions {x, y, z, w}
// or [x, y, z, w].  Everything else (robot state, allowed collision
// matrix, octomap, colours, subframes) is ignored.
#pragma once

#include "world/world.hpp"

#include <string>

namespace octoprox {

// Throws ApiError naming `source`, the line and the field on bad input.
void read_scene_yaml(const std::string &text, const std::string &source, World &world);

}  // namespace octoprox
