// MoveIt's shapes and poses as the library's, checked: the readers of
// both scene formats build their objects with these.
//   box       full edge lengths along x, y, z, centred (as opx_shape)
//   sphere    radius
//   cylinder  radius and full length along z, centred (MoveIt's
//             SolidPrimitive gives [height, radius], the .scene text
//             "radius length": each reader puts them in this order)
//   mesh      triangles over vertices (a surface, as a link's mesh)
#pragma once

#include "world/scene_update.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace octoprox {

ShapeDef scene_box(const Vec3 &size, const SceneWhere &where);
ShapeDef scene_sphere(double radius, const SceneWhere &where);
ShapeDef scene_cylinder(double radius, double length, const SceneWhere &where);
// Indices must be below vertices.size() (checked); unused vertices are dropped.
ShapeDef scene_mesh(std::vector<Vec3> vertices, std::vector<std::array<uint32_t, 3>> triangles,
                    const SceneWhere &where);

// A position and a quaternion x y z w, finite; the quaternion is
// normalised, and all zeros is the identity (as MoveIt reads a pose
// message whose orientation was left out).
Pose scene_pose(const Vec3 &position, const std::array<double, 4> &quaternion_xyzw, const SceneWhere &where);

}  // namespace octoprox
