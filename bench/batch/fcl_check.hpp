// FCL doing what the batch call does, as MoveIt does it: the robot's
// objects (paper_tables::FclRobot) against the map as an fcl::OcTree, then
// against each other through the manager's self-collision, skipping pairs
// of one link and the disabled pairs (the SRDF's, for the arms the
// adjacent links); both stop at the first contact.  Placing the objects at
// a configuration's link poses is FCL's FK step, left out of the timing as
// in Table IV.
#pragma once

#include <vector>

#include "bench_scene.hpp"

namespace batch_bench {

class FclCheck {
public:
    FclCheck(Robot &robot, fcl::CollisionObjectd &octree);

    void place(const std::vector<opx_pose> &link_poses) { robot_.set_link_poses(link_poses); }
    bool world_collides();
    bool self_collides();

private:
    paper_tables::FclRobot &robot_;
    fcl::CollisionObjectd &octree_;
    std::vector<char> allowed_;  // links x links: 1 where the pair is checked
    size_t links_ = 0;
};

}  // namespace batch_bench
