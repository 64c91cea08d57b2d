// A robot's joint tree and its forward kinematics (FK).  Joints keep the
// model's order; everything FK needs per call (a parents-first order,
// fixed origins, resolved mimic masters) is computed once in build(), so
// link_poses() allocates nothing and touches each joint once.
#pragma once

#include "geometry/pose.hpp"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace octoprox {

// Values equal to the OPX_JOINT_* codes of the C ABI.
enum class JointType : int { kFixed = 0, kRevolute, kContinuous, kPrismatic, kFloating, kPlanar };

constexpr uint32_t kNoIndex = UINT32_MAX;

// Largest multiplier or offset a chain of mimic joints may compose to:
// positions stay finite for any sane joint value.
constexpr double kMaxMimicFactor = 1e12;

struct Joint {
    std::string name;
    JointType type = JointType::kFixed;
    uint32_t parent_link = kNoIndex, child_link = kNoIndex;
    Pose origin;                 // child link frame in the parent link frame at 0
    Vec3 axis = Vec3::UnitX();   // unit, child link frame
    bool has_limits = false;
    double lower = 0.0, upper = 0.0, velocity = 0.0, effort = 0.0;
    uint32_t mimic = kNoIndex;   // the joint this one copies
    double multiplier = 1.0, offset = 0.0;

    bool moves() const {
        return type == JointType::kRevolute || type == JointType::kContinuous || type == JointType::kPrismatic;
    }
};

class JointTree {
public:
    // Checks the tree (every link but the root is the child of exactly one
    // joint, no cycles, mimic joints exist and do not loop, mimic chains
    // compose to at most kMaxMimicFactor) and precomputes
    // the FK order.  Throws ApiError(OPX_ERROR_CORRUPT) naming `source`.
    void build(std::vector<Joint> joints, size_t link_count, uint32_t root_link, const std::string &source);

    bool empty() const { return link_count_ == 0; }
    size_t joint_count() const { return joints_.size(); }
    size_t link_count() const { return link_count_; }
    uint32_t root_link() const { return root_link_; }
    const Joint &joint(uint32_t index) const { return joints_[index]; }
    uint32_t find(const std::string &name) const;  // kNoIndex when absent
    // The joints FK moves by their own value (revolute, continuous and
    // prismatic joints that mimic none), in model order: every joint's
    // position follows from theirs.
    const std::vector<uint32_t> &active_joints() const { return active_; }
    // Where a moving joint's position comes from: multiplier(j) times the
    // commanded value of master(j), plus an offset, composed along mimic
    // chains (a joint that mimics none: itself, 1).
    uint32_t master(uint32_t joint) const { return master_[joint]; }
    double multiplier(uint32_t joint) const { return multiplier_[joint]; }

    // The values callers set, per joint; FK reads positions().
    void set_commanded(const double *values);  // joint_count() values
    void set_commanded(uint32_t joint, double value) { commanded_[joint] = value; }
    void set_active_commanded(const double *values);  // active_joints().size() values
    void update_positions();                    // after set_commanded
    const std::vector<double> &positions() const { return positions_; }

    // Poses of links 0..link_count()-1 in the map frame; `poses` must
    // hold at least link_count() entries.
    void link_poses(const Pose &base, std::vector<Pose> &poses) const;

    // The same FK on values the caller holds, leaving the tree's own
    // untouched (any number of threads at once): `commanded` and
    // `positions` hold joint_count() values, `poses` link_count().
    void positions_from(const double *commanded, double *positions) const;
    void link_poses(const Pose &base, const double *positions, Pose *poses) const;
    // The FK order (parents first) cut to the joints that lead to a link
    // flagged in `needed` (per link): the others only pose links no one
    // reads (a robot's sensor frames, links without shapes below them).
    std::vector<uint32_t> order_toward(const std::vector<uint8_t> &needed) const;
    // FK again along such an order after a change from `previous`
    // positions (and, when base_moved, a new base): only the links below a
    // joint whose position changed, or below a link that moved, are
    // recomputed; `poses` holds the poses at `previous` and gets the new
    // ones, bit for bit as link_poses computes them.  `moved` (link_count()
    // flags) tells which links moved; the links the order leaves out keep
    // their poses and flags.
    void update_link_poses(const Pose &base, bool base_moved, const double *positions, const double *previous,
                           Pose *poses, uint8_t *moved, const std::vector<uint32_t> &order) const;

private:
    // child = parent * origin * motion(q)
    void compose(uint32_t j, const Pose &parent, double q, Pose &child) const;
    void classify_motions();
    void check_links(const std::string &source) const;
    void order_joints(const std::string &source);
    void resolve_mimics(const std::string &source);
    void compose_mimic(uint32_t joint, const std::string &source);
    void find_active_joints();

    std::vector<Joint> joints_;
    std::unordered_map<std::string, uint32_t> by_name_;
    std::vector<uint32_t> order_;      // joint indices, parents first
    std::vector<uint32_t> master_;     // per joint: the non-mimic joint it follows
    std::vector<double> multiplier_, offset_;  // composed along mimic chains
    std::vector<double> commanded_, positions_;
    std::vector<uint32_t> active_;     // model indices of the active joints
    // The joints that move, with where their position comes from, apart
    // from the Joint records: positions_from reads only these.
    struct MovingJoint {
        uint32_t joint, master;
        bool master_moves;
        double multiplier, offset;
    };
    std::vector<MovingJoint> moving_;
    // Per joint, what compose() may skip: an origin without rotation, and
    // an axis along x, y or z (0, 1, 2; -1: another), with its sign: most
    // URDF joints turn about a frame axis, a rotation of two columns.
    std::vector<uint8_t> origin_turns_;
    std::vector<int8_t> axis_index_;
    std::vector<double> axis_sign_;
    size_t link_count_ = 0;
    uint32_t root_link_ = kNoIndex;
};

}  // namespace octoprox
