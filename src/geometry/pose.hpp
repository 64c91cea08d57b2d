// Rigid transforms used inside the library (Eigen, double precision).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace octoprox {

using Vec3 = Eigen::Vector3d;

// The pose of a child frame in a parent frame: p_parent = rotation * p_child + translation.
struct Pose {
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    Vec3 translation = Vec3::Zero();

    Vec3 apply(const Vec3 &point) const { return rotation * point + translation; }
};

// From position + quaternion (x, y, z, w; ROS order), normalising the
// quaternion.  The caller has checked that it is finite and non-zero.
inline Pose pose_from_ros(const double position[3], const double quaternion_xyzw[4]) {
    Eigen::Quaterniond q(quaternion_xyzw[3], quaternion_xyzw[0], quaternion_xyzw[1],
                         quaternion_xyzw[2]);
    q.normalize();
    Pose pose;
    pose.rotation = q.toRotationMatrix();
    pose.translation = Vec3(position[0], position[1], position[2]);
    return pose;
}

}  // namespace octoprox
