#include "capi/checks.hpp"

namespace octoprox::capi {

bool pose_is_valid(const opx_pose &pose) {
    double norm2 = 0.0;
    for (int i = 0; i < 3; ++i)
        if (!std::isfinite(pose.position[i])) return false;
    for (int i = 0; i < 4; ++i) {
        if (!std::isfinite(pose.orientation[i])) return false;
        norm2 += pose.orientation[i] * pose.orientation[i];
    }
    return norm2 >= 1e-12;
}

Pose read_pose(const opx_pose &pose, const char *argument) {
    double norm2 = 0.0;
    for (int i = 0; i < 3; ++i) {
        if (!std::isfinite(pose.position[i]))
            throw_invalid(format("%s.position[%d] is %g, not a finite number", argument, i,
                                 pose.position[i]));
    }
    for (int i = 0; i < 4; ++i) {
        if (!std::isfinite(pose.orientation[i]))
            throw_invalid(format("%s.orientation[%d] is %g, not a finite number", argument, i,
                                 pose.orientation[i]));
        norm2 += pose.orientation[i] * pose.orientation[i];
    }
    // A quaternion this far from unit length is a caller's bug (all zeros:
    // an uninitialised pose), not rounding to normalise away.
    if (norm2 < 1e-12)
        throw_invalid(format("%s.orientation is a zero quaternion (x y z w, ROS order; identity is "
                             "0 0 0 1)",
                             argument));
    return pose_from_ros(pose.position, pose.orientation);
}

}  // namespace octoprox::capi
