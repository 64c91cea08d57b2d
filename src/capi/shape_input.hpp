// Shapes across the C ABI (opx_shape), shared by link sets and worlds:
// a caller's shape read, versioned and checked, and a stored shape's ABI
// view.
#pragma once

#include "robot/shape.hpp"

#include <octoprox/linkset.h>

namespace octoprox::capi {

// Throws ApiError (invalid argument) naming `argument` unless value is a
// positive length of at most kMaxMetres (base/bounds.hpp).
void require_positive(double value, const char *argument);
// Throws unless the pose's position is within +-kMaxMetres on every axis.
void require_position_in_bounds(const Pose &pose, const char *argument);
// Throws unless value is a finite length >= 0.
void require_padding(double value, const char *argument);

// The caller's shape checked (NULL, struct_size, sizes, vertices, indices)
// and turned into a definition in the shape frame.
ShapeDef read_shape(const opx_shape *shape);

// The ABI view of a stored shape; vertices and indices point into def.
opx_shape shape_to_abi(const ShapeDef &def);

}  // namespace octoprox::capi
