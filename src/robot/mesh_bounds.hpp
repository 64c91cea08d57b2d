// The exact axis-aligned box of a mesh at a pose, without placing its
// vertices: a pose update moves many meshes that no query then reaches.
#pragma once

#include "robot/shape.hpp"

namespace octoprox {

// Bounds of `def`'s triangles' vertices after p -> rotation * p + center,
// exactly those of the vertices PlacedShape::place_mesh computes; empty
// without triangles.  def's triangle tree must be built.
Aabb mesh_world_box(const ShapeDef &def, const Eigen::Matrix3d &rotation, const Vec3 &center);

}  // namespace octoprox
