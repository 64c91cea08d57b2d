#include "capi/batch_inputs.hpp"
#include "capi/world_handle.hpp"

#include "capi/checks.hpp"
#include "capi/request_checks.hpp"

namespace octoprox::capi {

namespace {

// Whether rows of `joint_count` values hold the active joints alone.
bool rows_of_active_joints(const JointTree &joints, size_t joint_count, int32_t joint_order) {
    const size_t model = joints.joint_count(), active = joints.active_joints().size();
    switch (joint_order) {
    case OPX_JOINTS_BY_COUNT:
        if (joint_count == model) return false;  // also when every joint is active: the same order
        if (joint_count == active) return true;
        throw_invalid(format("joint_count %zu is neither the number of joints, %zu (model order), nor the number "
                             "of active joints, %zu",
                             joint_count, model, active));
    case OPX_JOINTS_MODEL:
        if (joint_count != model)
            throw_invalid(format("joint_count %zu differs from the number of joints, %zu (request->joint_order is "
                                 "OPX_JOINTS_MODEL)",
                                 joint_count, model));
        return false;
    case OPX_JOINTS_ACTIVE:
        if (joint_count != active)
            throw_invalid(format("joint_count %zu differs from the number of active joints, %zu "
                                 "(request->joint_order is OPX_JOINTS_ACTIVE)",
                                 joint_count, active));
        return true;
    default:
        throw_invalid(format("request->joint_order is %d; OPX_JOINTS_BY_COUNT (0), OPX_JOINTS_MODEL (1) or "
                             "OPX_JOINTS_ACTIVE (2) is needed",
                             joint_order));
    }
}

}  // namespace

JointLayout read_joint_layout(const opx_linkset *links, size_t joint_count, int32_t joint_order) {
    const JointTree &joints = links->robot.joints;
    if (joints.empty()) throw ApiError(OPX_ERROR_UNSUPPORTED, "links has no joint tree (it was not made from URDF)");
    JointLayout layout;
    layout.joints = &joints;
    layout.joint_count = joint_count;
    if (rows_of_active_joints(joints, joint_count, joint_order)) layout.active = &joints.active_joints();
    return layout;
}

namespace {

void require_joint_values(const JointRows &rows, const char *argument) {
    std::vector<double> row(rows.joint_count);
    for (size_t r = 0; r < rows.count; ++r) {
        rows.read_values(r, row.data());
        for (size_t j = 0; j < rows.joint_count; ++j)  // the name is formatted only for a bad value
            if (!joint_position_in_range(row[j]))
                reject_joint_position(row[j], format("%s[row %zu][joint %zu]", argument, r, j).c_str());
    }
}

}  // namespace

JointRows read_joint_rows(const double *positions, size_t count, const JointLayout &layout, size_t stride,
                          const char *argument) {
    const size_t joint_count = layout.joint_count;
    const size_t row_bytes = joint_count * sizeof(double);
    if (stride != 0 && stride < row_bytes)
        throw_invalid(format("stride %zu is smaller than one row of %zu joints (%zu bytes)", stride, joint_count,
                             row_bytes));
    if (count > 0 && joint_count > 0) require_pointer(positions, argument);
    JointRows rows;
    rows.bytes = reinterpret_cast<const unsigned char *>(positions);
    rows.count = count, rows.joint_count = joint_count;
    rows.stride = stride != 0 ? stride : row_bytes;
    rows.active = layout.active;
    rows.active_model_count = layout.joints->joint_count();
    require_joint_values(rows, argument);
    return rows;
}

BasePoses read_base_poses(const opx_pose *poses, size_t count, size_t stride, size_t rows) {
    if (count != 0 && count != 1 && count != rows)
        throw_invalid(format("base_pose_count %zu is neither 0, 1 nor the row count %zu", count, rows));
    if (stride != 0 && stride < sizeof(opx_pose))
        throw_invalid(format("base_pose_stride %zu is smaller than one opx_pose (%zu bytes)", stride,
                             sizeof(opx_pose)));
    BasePoses bases;
    if (count == 0) {
        bases.poses.emplace_back();
        return bases;
    }
    require_pointer(poses, "base_poses");
    const size_t step = stride != 0 ? stride : sizeof(opx_pose);
    const auto *bytes = reinterpret_cast<const unsigned char *>(poses);
    bases.poses.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        opx_pose pose;
        std::memcpy(&pose, bytes + i * step, sizeof pose);
        bases.poses.push_back(read_pose_lazily(pose, [i] { return format("base_poses[%zu]", i); }));
    }
    return bases;
}

void require_rows(size_t rows, const char *count_argument, size_t capacity) {
    if (rows == 0) throw_invalid(format("%s is 0; give at least one row", count_argument));
    if (capacity < rows)
        throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                       format("capacity %zu is smaller than %s, %zu", capacity, count_argument, rows));
}

CollisionSettings yes_no_settings(int32_t unknown_policy, double occupancy_threshold, const SensorOctree *tree) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.unknown_policy = unknown_policy;
    request.occupancy_threshold = occupancy_threshold;
    request.max_contacts = 0;
    return settings_for_map(request, tree);
}

}  // namespace octoprox::capi
