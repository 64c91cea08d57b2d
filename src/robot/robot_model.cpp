#include "robot/robot_model.hpp"

namespace octoprox {

void RobotModel::apply(LinkSet &links, const Pose &base) {
    pose_scratch.resize(links.link_count());
    for (size_t i = joints.link_count(); i < links.link_count(); ++i)
        pose_scratch[i] = links.link(static_cast<uint32_t>(i)).pose;
    joints.link_poses(base, pose_scratch);
    links.set_poses(pose_scratch);
}

}  // namespace octoprox
