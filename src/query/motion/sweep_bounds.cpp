#include "query/motion/sweep_bounds.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

// The farthest point of a box from `origin`: its farthest corner.
double farthest_corner(const Aabb &box, const Vec3 &origin) {
    const Vec3 far = (box.lo - origin).cwiseAbs().cwiseMax((box.hi - origin).cwiseAbs());
    return far.norm();
}

}  // namespace

void SweepBounds::compute(const JointTree &joints, const LinkSet &posed, const std::vector<double> &start,
                          const std::vector<double> &goal, bool self_collision) {
    joints_ = &joints;
    const size_t count = joints.joint_count();
    change_.assign(count, 0.0), offset_.assign(count, 0.0), prismatic_.assign(count, 0);
    for (uint32_t j = 0; j < count; ++j) {
        const Joint &joint = joints.joint(j);
        offset_[j] = joint.origin.translation.norm();
        if (!joint.moves()) continue;
        change_[j] = std::fabs(goal[j] - start[j]);
        if (joint.type == JointType::kPrismatic) {
            prismatic_[j] = 1;
            offset_[j] += std::max(std::fabs(start[j]), std::fabs(goal[j]));
        }
    }
    compute_reach(posed);
    compute_rates(joints);
    if (self_collision) compute_self_rate(posed);
}

// Each link's shapes' boxes (map frame, inflated shapes, the link posed
// by FK) bound its shapes; their farthest corner from the link's origin
// bounds its points at every configuration, the shapes being rigid in it.
void SweepBounds::compute_reach(const LinkSet &posed) {
    const size_t links = joints_->link_count();
    reach_.assign(links, 0.0);
    for (const PlacedShape &shape : posed.placed()) {
        if (shape.link >= links || shape.box.empty()) continue;
        const Vec3 &origin = posed.link(shape.link).pose.translation;
        reach_[shape.link] = std::max(reach_[shape.link], farthest_corner(shape.box, origin));
    }
}

void SweepBounds::compute_rates(const JointTree &joints) {
    const size_t links = joints.link_count();
    parent_joint_.assign(links, kNoIndex), depth_.assign(links, 0);
    for (uint32_t j = 0; j < joints.joint_count(); ++j) parent_joint_[joints.joint(j).child_link] = j;
    rate_.assign(links, 0.0);
    largest_ = 0.0;
    for (uint32_t link = 0; link < links; ++link) {
        double radius = reach_[link], rate = 0.0;
        uint32_t depth = 0;
        for (uint32_t at = link; parent_joint_[at] != kNoIndex; ++depth) {
            const uint32_t j = parent_joint_[at];
            rate += change_[j] * (prismatic_[j] ? 1.0 : radius);
            radius += offset_[j];
            at = joints.joint(j).parent_link;
        }
        rate_[link] = rate, depth_[link] = depth;
        largest_ = std::max(largest_, rate);
    }
}

// Both links' terms of the joints below their lowest common ancestor.
double SweepBounds::pair_rate(uint32_t a, uint32_t b) const {
    double radius[2] = {reach_[a], reach_[b]}, rate = 0.0;
    uint32_t at[2] = {a, b};
    while (at[0] != at[1]) {
        const int deeper = depth_[at[0]] >= depth_[at[1]] ? 0 : 1;
        const uint32_t j = parent_joint_[at[deeper]];
        if (j == kNoIndex) break;  // two roots: not one tree (never for a URDF)
        rate += change_[j] * (prismatic_[j] ? 1.0 : radius[deeper]);
        radius[deeper] += offset_[j];
        at[deeper] = joints_->joint(j).parent_link;
    }
    return rate;
}

// Over the enabled pairs of links with enabled shapes; an attached object
// meets links the pair matrix does not say (attached_meets_link), so with
// one every pair counts.  A link FK does not move has the other link's
// whole rate as pair rate.
void SweepBounds::compute_self_rate(const LinkSet &posed) {
    self_rate_ = 0.0;
    const size_t links = joints_->link_count();
    std::vector<uint8_t> shaped(posed.link_count(), 0);
    for (const PlacedShape &shape : posed.placed())
        if (!shape.box.empty()) shaped[shape.link] = 1;
    for (size_t link = links; link < shaped.size(); ++link)
        if (shaped[link]) self_rate_ = largest_;
    const bool every_pair = posed.attached_count() > 0;
    const LinkPairs &pairs = posed.pairs();
    for (uint32_t a = 0; a < links; ++a) {
        if (!shaped[a]) continue;
        for (uint32_t b = a + 1; b < links; ++b)
            if (shaped[b] && (every_pair || pairs.enabled(a, b)))
                self_rate_ = std::max(self_rate_, pair_rate(a, b));
    }
}

}  // namespace octoprox
