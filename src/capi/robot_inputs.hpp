// What the forward-kinematics shims share: the joint tree of a link set
// made from URDF, the root link's pose, and the poses FK then sets.
#pragma once

#include "capi/checks.hpp"
#include "capi/handles.hpp"

#include <octoprox/common.h>

namespace octoprox::capi {

// The joint tree of a link set made from URDF; others have none
// (OPX_ERROR_UNSUPPORTED).
inline JointTree &require_joints(opx_linkset *links) {
    require_pointer(links, "links");
    if (links->robot.joints.empty())
        throw ApiError(OPX_ERROR_UNSUPPORTED, "links has no joint tree (it was not made from URDF)");
    return links->robot.joints;
}

// The root link's pose in the map frame (NULL: identity).
inline Pose read_base_pose(const opx_pose *base_pose) {
    return base_pose == nullptr ? Pose() : read_pose(*base_pose, "base_pose");
}

// `count` joint values, each a valid joint position; a bad one is named
// "positions[i]".
inline void require_joint_values(const double *positions, size_t count) {
    if (count > 0) require_pointer(positions, "positions");
    for (size_t i = 0; i < count; ++i)  // the name is formatted only for a bad value
        if (!joint_position_in_range(positions[i]))
            reject_joint_position(positions[i], format("positions[%zu]", i).c_str());
}

// FK from the joint tree's commanded values: every link pose of the set.
inline void apply_joint_positions(opx_linkset *links, const Pose &base) {
    links->robot.joints.update_positions();
    links->robot.apply(links->links, base);
}

// A pose in the ABI's form: position and unit quaternion x y z w.
inline opx_pose pose_to_abi(const Pose &pose) {
    const Eigen::Quaterniond q(pose.rotation);
    return opx_pose{{pose.translation.x(), pose.translation.y(), pose.translation.z()}, {q.x(), q.y(), q.z(), q.w()}};
}

}  // namespace octoprox::capi
