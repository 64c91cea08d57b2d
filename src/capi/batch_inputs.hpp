// Reading the batch queries' arrays (batch.h): joint vectors, root poses
// and output capacities, each checked with a message naming the argument.
#pragma once

#include "capi/handles.hpp"
#include "query/batch/batch_types.hpp"

#include <octoprox/batch.h>

namespace octoprox::capi {

// The joint tree the rows are for, and what a row holds: joint_count
// values, in model order or (active not null) the active joints alone.
struct JointLayout {
    const JointTree *joints = nullptr;
    size_t joint_count = 0;
    const std::vector<uint32_t> *active = nullptr;  // JointTree::active_joints() for rows of active joints
};

// The joint tree of a link set made from URDF (OPX_ERROR_UNSUPPORTED for
// others) and the order of rows of `joint_count` values, as
// `joint_order` (OPX_JOINTS_*, request->joint_order) allows.
JointLayout read_joint_layout(const opx_linkset *links, size_t joint_count, int32_t joint_order);

// `count` rows laid out as `layout` says, `stride` bytes apart (0:
// packed), every value a valid joint position; `argument` names the array.
JointRows read_joint_rows(const double *positions, size_t count, const JointLayout &layout, size_t stride,
                          const char *argument);

// 0 poses (the identity), 1 (shared) or `rows` poses, `stride` bytes apart.
BasePoses read_base_poses(const opx_pose *poses, size_t count, size_t stride, size_t rows);

// The row count: not 0, and no more than the outputs' capacity
// (OPX_ERROR_BUFFER_TOO_SMALL).
void require_rows(size_t rows, const char *count_argument, size_t capacity);

// Collision settings of a yes/no check (no contacts, no cost); tree null:
// the fields checked, the map's not used (a query with a world alone).
CollisionSettings yes_no_settings(int32_t unknown_policy, double occupancy_threshold, const SensorOctree *tree);

}  // namespace octoprox::capi
