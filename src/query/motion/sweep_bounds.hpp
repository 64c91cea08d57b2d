// How far a link's points can move along a straight joint-space motion:
// the displacement bounds certified motion checks advance by
// (docs/geometry.md, "Certified motions").
//
// For a link L and a joint j on its chain to the root, every point of L's
// shapes (padding and attached objects included) lies within R(j, L) of
// the origin of j's frame, whatever the joint positions: R is the
// farthest point of L from L's own frame, plus, up the chain to j, each
// joint's fixed offset and each prismatic joint's largest travel along
// the motion.  A revolute joint turning by dq then moves those points at
// most R(j, L) |dq| (they are at most R from its axis), a prismatic joint
// by |dq|.  Along the motion start + s (goal - start), a point of L thus
// moves at most rate(L) |s1 - s0| between parameters s0 and s1, rate(L)
// being the sum over the chain's joints of R(j, L) |goal_j - start_j| (1
// in place of R for a prismatic joint).  Links FK does not move (the
// root, links added after loading) have rate 0.
//
// Two links move relative to each other only by the joints below their
// lowest common ancestor link, rigid motions of both leaving their
// distance as it is: pair_rate(a, b) sums those joints' terms alone.
#pragma once

#include "robot/joint_tree.hpp"
#include "robot/linkset.hpp"

#include <vector>

namespace octoprox {

class SweepBounds {
public:
    // The rates of the motion from positions `start` to `goal` (every
    // joint's position, mimic joints resolved: PosedRobot::positions) of
    // `posed`, a copy of the robot posed by FK on `joints` at any
    // configuration (its shapes' boxes give each link's reach);
    // self_rate() only with `self_collision`.
    void compute(const JointTree &joints, const LinkSet &posed, const std::vector<double> &start,
                 const std::vector<double> &goal, bool self_collision);

    // Metres per unit of the motion's parameter.
    double rate(uint32_t link) const { return link < rate_.size() ? rate_[link] : 0.0; }
    double largest_rate() const { return largest_; }
    // The largest pair rate over the pairs self-collision checks.
    double self_rate() const { return self_rate_; }

private:
    double reach(uint32_t link) const { return reach_[link]; }
    void compute_reach(const LinkSet &posed);
    void compute_rates(const JointTree &joints);
    double pair_rate(uint32_t a, uint32_t b) const;
    void compute_self_rate(const LinkSet &posed);

    // Per link of the joint tree: the joint whose child it is (kNoIndex:
    // none), its depth, its farthest shape point from its frame, its rate.
    std::vector<uint32_t> parent_joint_;
    std::vector<uint32_t> depth_;
    std::vector<double> reach_, rate_;
    // Per joint: |goal - start| (0 for a joint that does not move), and the
    // bound on its child frame's offset from its parent's.
    std::vector<double> change_, offset_;
    std::vector<uint8_t> prismatic_;
    const JointTree *joints_ = nullptr;
    double largest_ = 0.0, self_rate_ = 0.0;
};

}  // namespace octoprox
