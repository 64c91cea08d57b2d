// A robot a batch worker moves configuration after configuration: its own
// copy of the caller's link set, posed by forward kinematics on the
// caller's joint tree (read-only), so the caller's set never moves and any
// number of workers may pose copies of it at once.
#pragma once

#include "robot/joint_tree.hpp"
#include "robot/linkset.hpp"

#include <memory>
#include <vector>

namespace octoprox {

class PosedRobot {
public:
    // Ready to pose `links` with `joints` (the caller's; both read-only and
    // alive while this robot is used).  The copy is made again only when
    // the caller's set changed in more than its poses; links the joint tree
    // does not move take the caller's current poses.
    void bind(const LinkSet &links, const JointTree &joints);

    // FK at `commanded` (joint_count() values, model order) with the root
    // link at `base` (map frame); the copy's links take the poses.
    const LinkSet &pose(const double *commanded, const Pose &base);
    // FK alone: the link poses at `commanded` (link order; those of links
    // with no shape at or below them may be stale), the copy's shapes left
    // where they were.  A later pose() places what moved.
    const std::vector<Pose> &pose_links(const double *commanded, const Pose &base);

    // Every joint's position FK uses for `commanded` (mimic joints
    // resolved; fixed, floating and planar joints 0).
    void positions(const double *commanded, std::vector<double> &out) const;
    // The copy's link poses after the last pose(), link order; a link
    // with no shape at or below it keeps a pose of an earlier one.
    const std::vector<Pose> &link_poses() const { return poses_; }

    size_t joint_count() const { return joints_->joint_count(); }
    const LinkSet &links() const { return *copy_; }

private:
    void forward_kinematics(const Pose &base);

    std::unique_ptr<LinkSet> copy_;
    uint64_t source_ = 0;  // identity of the set copied
    const JointTree *joints_ = nullptr;
    // FK redoes only what changed since the last pose (a planner's batch
    // moves an arm or two of a robot): positions_ and poses_ hold the last
    // configuration's, previous_ the one before.
    std::vector<double> positions_, previous_;
    std::vector<Pose> poses_;
    std::vector<uint8_t> moved_;
    std::vector<uint32_t> fk_order_;  // the joints FK updates after the first pose
    Pose base_;
    bool posed_ = false;  // poses_ hold an FK result of positions_ and base_
    // The copy's links are at poses_ (the last pose(), no pose_links() since).
    bool copy_holds_previous_ = false;
};

}  // namespace octoprox
