// Reading the batch queries' arrays (batch.h): joint vectors, root poses
// and output capacities, each checked with a message naming the argument.
#pragma once

#include "capi/handles.hpp"
#include "query/batch/batch_types.hpp"

#include <octoprox/batch.h>

namespace octoprox::capi {

// The joint tree of a link set made from URDF (OPX_ERROR_UNSUPPORTED for
// others), whose joint count must equal `joint_count`.
const JointTree &require_joint_tree(const opx_linkset *links, size_t joint_count);

// `count` rows of `joint_count` doubles `stride` bytes apart (0: packed),
// every value a valid joint position; `argument` names the array.
JointRows read_joint_rows(const double *positions, size_t count, size_t joint_count, size_t stride,
                          const char *argument);

// 0 poses (the identity), 1 (shared) or `rows` poses, `stride` bytes apart.
BasePoses read_base_poses(const opx_pose *poses, size_t count, size_t stride, size_t rows);

// The row count: not 0, and no more than the outputs' capacity
// (OPX_ERROR_BUFFER_TOO_SMALL).
void require_rows(size_t rows, const char *count_argument, size_t capacity);

// Collision settings of a yes/no check (no contacts, no cost).
CollisionSettings yes_no_settings(int32_t unknown_policy, double occupancy_threshold, const SensorOctree &tree);

}  // namespace octoprox::capi
