#include "robot/joint_tree.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace octoprox {
namespace {

[[noreturn]] void throw_tree_error(const std::string &source, const std::string &what) {
    throw_corrupt(source + ": " + what);
}

}  // namespace

void JointTree::build(std::vector<Joint> joints, size_t link_count, uint32_t root_link,
                      const std::string &source) {
    joints_ = std::move(joints);
    link_count_ = link_count;
    root_link_ = root_link;
    by_name_.clear();
    for (uint32_t j = 0; j < joints_.size(); ++j)
        if (!by_name_.emplace(joints_[j].name, j).second)
            throw_tree_error(source, "two joints are named '" + joints_[j].name + "'");
    check_links(source);
    order_joints(source);
    resolve_mimics(source);
    classify_motions();
    find_active_joints();
    commanded_.assign(joints_.size(), 0.0);
    positions_.assign(joints_.size(), 0.0);
    update_positions();
}

uint32_t JointTree::find(const std::string &name) const {
    const auto it = by_name_.find(name);
    return it == by_name_.end() ? kNoIndex : it->second;
}

void JointTree::check_links(const std::string &source) const {
    if (root_link_ >= link_count_) throw_tree_error(source, "the model has no root link");
    std::vector<bool> is_child(link_count_, false);
    for (const Joint &j : joints_) {
        if (j.parent_link >= link_count_ || j.child_link >= link_count_)
            throw_tree_error(source, "joint '" + j.name + "' names a link that does not exist");
        if (j.child_link == root_link_ || is_child[j.child_link])
            throw_tree_error(source, "joint '" + j.name + "': its child link has another parent joint");
        is_child[j.child_link] = true;
    }
    for (size_t link = 0; link < link_count_; ++link)
        if (link != root_link_ && !is_child[link])
            throw_tree_error(source, "link " + std::to_string(link) + " is neither the root nor the child of a joint");
}

// Parents before children: a walk down from the root.  A joint the walk
// does not reach hangs off a cycle or a second root.
void JointTree::order_joints(const std::string &source) {
    std::vector<std::vector<uint32_t>> children(link_count_);
    for (uint32_t j = 0; j < joints_.size(); ++j) children[joints_[j].parent_link].push_back(j);
    order_.clear();
    std::vector<uint32_t> stack{root_link_};
    while (!stack.empty()) {
        const uint32_t link = stack.back();
        stack.pop_back();
        for (uint32_t j : children[link]) {
            order_.push_back(j);
            stack.push_back(joints_[j].child_link);
        }
    }
    if (order_.size() != joints_.size())
        throw_tree_error(source, "the joints do not form one tree below the root link");
}

// A mimic of a mimic follows the first joint of its chain:
// a = m1 * b + o1, b = m2 * c + o2  =>  a = m1 m2 c + (m1 o2 + o1).
// A joint's composition is kept once known, so every chain is walked once
// (linear time, however long the chains).
void JointTree::resolve_mimics(const std::string &source) {
    const size_t n = joints_.size();
    master_.assign(n, kNoIndex);
    multiplier_.assign(n, 1.0);
    offset_.assign(n, 0.0);
    std::vector<uint32_t> path;
    std::vector<bool> on_path(n, false);
    for (uint32_t j = 0; j < n; ++j) {
        uint32_t current = j;
        path.clear();
        while (master_[current] == kNoIndex && joints_[current].mimic != kNoIndex) {
            if (on_path[current]) throw_tree_error(source, "joint '" + joints_[j].name + "': its mimic joints form a loop");
            on_path[current] = true;
            path.push_back(current);
            current = joints_[current].mimic;
        }
        if (master_[current] == kNoIndex) master_[current] = current;  // a joint that mimics none
        for (auto k = path.rbegin(); k != path.rend(); ++k) compose_mimic(*k, source);
        for (uint32_t k : path) on_path[k] = false;
    }
}

// Joint k from the composition of the joint it mimics, already known.
void JointTree::compose_mimic(uint32_t k, const std::string &source) {
    const Joint &joint = joints_[k];
    master_[k] = master_[joint.mimic];
    multiplier_[k] = joint.multiplier * multiplier_[joint.mimic];
    offset_[k] = joint.multiplier * offset_[joint.mimic] + joint.offset;
    if (!(std::fabs(multiplier_[k]) <= kMaxMimicFactor && std::fabs(offset_[k]) <= kMaxMimicFactor))
        throw_tree_error(source, "joint '" + joint.name + "': its mimic chain composes to a multiplier or offset beyond +-1e12");
}

void JointTree::set_commanded(const double *values) {
    for (size_t j = 0; j < commanded_.size(); ++j) commanded_[j] = values[j];
}

void JointTree::find_active_joints() {
    active_.clear();
    moving_.clear();
    for (uint32_t j = 0; j < joints_.size(); ++j) {
        if (!joints_[j].moves()) continue;
        if (joints_[j].mimic == kNoIndex) active_.push_back(j);
        moving_.push_back({j, master_[j], joints_[master_[j]].moves(), multiplier_[j], offset_[j]});
    }
}

// The other joints' commanded values are never read: positions_from takes
// a moving joint's value from the first joint of its mimic chain, which
// mimics none: an active joint, or one that does not move (value 0).
void JointTree::set_active_commanded(const double *values) {
    for (size_t i = 0; i < active_.size(); ++i) commanded_[active_[i]] = values[i];
}

void JointTree::update_positions() { positions_from(commanded_.data(), positions_.data()); }

void JointTree::positions_from(const double *commanded, double *positions) const {
    std::fill(positions, positions + joints_.size(), 0.0);
    for (const MovingJoint &m : moving_) {
        const double master_value = m.master_moves ? commanded[m.master] : 0.0;
        positions[m.joint] = m.multiplier * master_value + m.offset;
    }
}

void JointTree::link_poses(const Pose &base, std::vector<Pose> &poses) const {
    link_poses(base, positions_.data(), poses.data());
}

void JointTree::link_poses(const Pose &base, const double *positions, Pose *poses) const {
    poses[root_link_] = base;
    for (uint32_t j : order_) {
        const Joint &joint = joints_[j];
        compose(j, poses[joint.parent_link], positions[j], poses[joint.child_link]);
    }
}

std::vector<uint32_t> JointTree::order_toward(const std::vector<uint8_t> &needed) const {
    // Children come after their parents in order_: walked backwards, a
    // link is needed once any link below it is.
    std::vector<uint8_t> below(link_count_, 0);
    for (size_t i = 0; i < link_count_ && i < needed.size(); ++i) below[i] = needed[i];
    for (auto j = order_.rbegin(); j != order_.rend(); ++j)
        if (below[joints_[*j].child_link]) below[joints_[*j].parent_link] = 1;
    std::vector<uint32_t> order;
    for (uint32_t j : order_)
        if (below[joints_[j].child_link]) order.push_back(j);
    return order;
}

void JointTree::update_link_poses(const Pose &base, bool base_moved, const double *positions,
                                  const double *previous, Pose *poses, uint8_t *moved,
                                  const std::vector<uint32_t> &order) const {
    moved[root_link_] = base_moved ? 1 : 0;
    if (base_moved) poses[root_link_] = base;
    for (uint32_t j : order) {
        const Joint &joint = joints_[j];
        // Bit for bit: -0.0 and 0.0 may give poses differing in a zero's sign.
        const bool changed = moved[joint.parent_link] != 0 || std::memcmp(&positions[j], &previous[j], sizeof(double)) != 0;
        moved[joint.child_link] = changed ? 1 : 0;
        if (changed) compose(j, poses[joint.parent_link], positions[j], poses[joint.child_link]);
    }
}

void JointTree::classify_motions() {
    const size_t n = joints_.size();
    origin_turns_.assign(n, 1);
    axis_index_.assign(n, -1);
    axis_sign_.assign(n, 1.0);
    for (size_t j = 0; j < n; ++j) {
        const Joint &joint = joints_[j];
        origin_turns_[j] = joint.origin.rotation == Eigen::Matrix3d::Identity() ? 0 : 1;
        for (int axis = 0; axis < 3; ++axis) {
            const double along = joint.axis[axis];
            if ((along == 1.0 || along == -1.0) && joint.axis.squaredNorm() == 1.0)
                axis_index_[j] = static_cast<int8_t>(axis), axis_sign_[j] = along;
        }
    }
}

namespace {

// rotation = rotation * (a turn of angle q about frame axis `axis`): only
// the two other columns change.
void turn_about_axis(Eigen::Matrix3d &rotation, int axis, double q) {
    const double c = std::cos(q), s = std::sin(q);
    const int a = (axis + 1) % 3, b = (axis + 2) % 3;
    const Vec3 col_a = rotation.col(a), col_b = rotation.col(b);
    rotation.col(a) = c * col_a + s * col_b;
    rotation.col(b) = c * col_b - s * col_a;
}

}  // namespace

void JointTree::compose(uint32_t j, const Pose &parent, double q, Pose &child) const {
    const Joint &joint = joints_[j];
    child.rotation = origin_turns_[j] ? Eigen::Matrix3d(parent.rotation * joint.origin.rotation) : parent.rotation;
    child.translation = parent.apply(joint.origin.translation);
    switch (joint.type) {
    case JointType::kRevolute:
    case JointType::kContinuous:
        if (axis_index_[j] >= 0) turn_about_axis(child.rotation, axis_index_[j], axis_sign_[j] * q);
        else child.rotation = child.rotation * Eigen::AngleAxisd(q, joint.axis).toRotationMatrix();
        break;
    case JointType::kPrismatic: child.translation += child.rotation * (q * joint.axis); break;
    default: break;
    }
}

}  // namespace octoprox
