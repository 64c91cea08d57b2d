#include "query/batch/posed_robot.hpp"

namespace octoprox {

void PosedRobot::bind(const LinkSet &links, const JointTree &joints) {
    if (!copy_ || source_ != links.identity() || copy_->generation() != links.generation()) {
        copy_ = std::make_unique<LinkSet>(links);
        source_ = links.identity();
    }
    joints_ = &joints;
    positions_.resize(joints.joint_count());
    poses_.resize(links.link_count());
    for (size_t i = joints.link_count(); i < links.link_count(); ++i)
        poses_[i] = links.link(static_cast<uint32_t>(i)).pose;
}

const LinkSet &PosedRobot::pose(const double *commanded, const Pose &base) {
    joints_->positions_from(commanded, positions_.data());
    joints_->link_poses(base, positions_.data(), poses_.data());
    copy_->set_poses(poses_);
    return *copy_;
}

void PosedRobot::positions(const double *commanded, std::vector<double> &out) const {
    out.resize(joints_->joint_count());
    joints_->positions_from(commanded, out.data());
}

}  // namespace octoprox
