#include "query/batch/posed_robot.hpp"

namespace octoprox {

void PosedRobot::bind(const LinkSet &links, const JointTree &joints) {
    const bool copied = !copy_ || source_ != links.identity() || copy_->generation() != links.generation();
    if (copied) {
        copy_ = std::make_unique<LinkSet>(links);
        // Each pose of the copy is checked once: cheap mesh boxes pay.
        copy_->set_mesh_box(MeshBox::kCheap);
        source_ = links.identity();
    }
    if (copied || joints_ != &joints) {
        // FK poses only the links that have shapes (own or attached) or
        // lead to one: the copy's other links are never read.
        std::vector<uint8_t> shaped(joints.link_count(), 0);
        for (const PlacedShape &shape : copy_->placed())
            if (shape.link < shaped.size()) shaped[shape.link] = 1;
        fk_order_ = joints.order_toward(shaped);
    }
    joints_ = &joints;
    positions_.resize(joints.joint_count());
    previous_.resize(joints.joint_count());
    moved_.resize(joints.link_count());
    poses_.resize(links.link_count());
    for (size_t i = joints.link_count(); i < links.link_count(); ++i)
        poses_[i] = links.link(static_cast<uint32_t>(i)).pose;
    posed_ = false;
    copy_holds_previous_ = false;
}

// FK's flags say which links moved since the poses it started from; the
// copy may skip the others when it holds those poses.
const LinkSet &PosedRobot::pose(const double *commanded, const Pose &base) {
    const bool from_copy = copy_holds_previous_ && posed_;
    pose_links(commanded, base);
    if (from_copy) copy_->set_poses(poses_, moved_.data(), moved_.size());
    else copy_->set_poses(poses_);
    copy_holds_previous_ = true;
    return *copy_;
}

const std::vector<Pose> &PosedRobot::pose_links(const double *commanded, const Pose &base) {
    copy_holds_previous_ = false;
    positions_.swap(previous_);
    joints_->positions_from(commanded, positions_.data());
    forward_kinematics(base);
    return poses_;
}

void PosedRobot::forward_kinematics(const Pose &base) {
    if (!posed_) {
        joints_->link_poses(base, positions_.data(), poses_.data());
        posed_ = true;
    } else {
        const bool base_moved = !(base.rotation == base_.rotation && base.translation == base_.translation);
        joints_->update_link_poses(base, base_moved, positions_.data(), previous_.data(), poses_.data(),
                                   moved_.data(), fk_order_);
    }
    base_ = base;
}

void PosedRobot::positions(const double *commanded, std::vector<double> &out) const {
    out.resize(joints_->joint_count());
    joints_->positions_from(commanded, out.data());
}

}  // namespace octoprox
