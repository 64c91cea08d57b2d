#include "capi/batch_inputs.hpp"

#include "capi/checks.hpp"
#include "capi/request_checks.hpp"

namespace octoprox::capi {

const JointTree &require_joint_tree(const opx_linkset *links, size_t joint_count) {
    const JointTree &joints = links->robot.joints;
    if (joints.empty()) throw ApiError(OPX_ERROR_UNSUPPORTED, "links has no joint tree (it was not made from URDF)");
    if (joint_count != joints.joint_count())
        throw_invalid(format("joint_count %zu differs from the number of joints, %zu", joint_count,
                             joints.joint_count()));
    return joints;
}

namespace {

void require_joint_values(const JointRows &rows, const char *argument) {
    std::vector<double> row(rows.joint_count);
    for (size_t r = 0; r < rows.count; ++r) {
        rows.read(r, row.data());
        for (size_t j = 0; j < rows.joint_count; ++j)  // the name is formatted only for a bad value
            if (!joint_position_in_range(row[j]))
                reject_joint_position(row[j], format("%s[row %zu][joint %zu]", argument, r, j).c_str());
    }
}

}  // namespace

JointRows read_joint_rows(const double *positions, size_t count, size_t joint_count, size_t stride,
                          const char *argument) {
    const size_t row_bytes = joint_count * sizeof(double);
    if (stride != 0 && stride < row_bytes)
        throw_invalid(format("stride %zu is smaller than one row of %zu joints (%zu bytes)", stride, joint_count,
                             row_bytes));
    if (count > 0 && joint_count > 0) require_pointer(positions, argument);
    JointRows rows;
    rows.bytes = reinterpret_cast<const unsigned char *>(positions);
    rows.count = count, rows.joint_count = joint_count;
    rows.stride = stride != 0 ? stride : row_bytes;
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

CollisionSettings yes_no_settings(int32_t unknown_policy, double occupancy_threshold, const SensorOctree &tree) {
    CollisionSettings settings;
    settings.unknown_occupied = read_unknown_policy(unknown_policy, "request->unknown_policy");
    settings.threshold_log_odds = read_threshold_log_odds(occupancy_threshold, tree, "request->occupancy_threshold");
    settings.max_contacts = 0;
    return settings;
}

}  // namespace octoprox::capi
