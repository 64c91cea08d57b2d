// What a link set made from URDF knows beyond its links and shapes: the
// joint tree with the current joint positions, and SRDF disabled pairs.
#pragma once

#include "robot/joint_tree.hpp"
#include "robot/linkset.hpp"

#include <array>
#include <vector>

namespace octoprox {

struct RobotModel {
    JointTree joints;
    std::vector<std::array<uint32_t, 2>> disabled_pairs;  // link indices
    std::vector<Pose> pose_scratch;  // FK output, kept to allocate nothing per call

    // Poses every link of `links` from the joint tree's current positions
    // (links not in the tree keep theirs) and refits the set.
    void apply(LinkSet &links, const Pose &base);
};

}  // namespace octoprox
