#include "octree/sensor_octree.hpp"

#include "base/error.hpp"
#include "octree/point_extent.hpp"
#include "octree/traverse.hpp"

#include "octree/bounded_tree.hpp"

#include <algorithm>
#include <atomic>
#include <cstring>

namespace octoprox {

void validate_params(const OctreeParams &p, const char *argument) {
    auto check_probability = [&](double value, const char *field) {
        if (!(value > 0.0 && value < 1.0))
            throw_invalid(format("%s.%s is %g; a probability strictly between 0 and 1 is needed",
                                 argument, field, value));
    };
    if (!resolution_in_range(p.resolution))
        throw_invalid(format("%s.resolution is %g; a cell edge from %g to %g metres is needed",
                             argument, p.resolution, kMinResolution, kMaxResolution));
    check_probability(p.prob_hit, "prob_hit");
    check_probability(p.prob_miss, "prob_miss");
    check_probability(p.clamp_min, "clamp_min");
    check_probability(p.clamp_max, "clamp_max");
    check_probability(p.occupied_threshold, "occupied_threshold");
    check_probability(p.free_threshold, "free_threshold");
    if (!(p.prob_hit > 0.5))
        throw_invalid(format("%s.prob_hit is %g; a hit must raise occupancy (> 0.5)", argument,
                             p.prob_hit));
    if (!(p.prob_miss < 0.5))
        throw_invalid(format("%s.prob_miss is %g; a miss must lower occupancy (< 0.5)", argument,
                             p.prob_miss));
    if (!(p.clamp_min < p.clamp_max))
        throw_invalid(format("%s.clamp_min %g is not below clamp_max %g", argument, p.clamp_min,
                             p.clamp_max));
    if (!(p.free_threshold <= p.occupied_threshold))
        throw_invalid(format("%s.free_threshold %g is above occupied_threshold %g", argument,
                             p.free_threshold, p.occupied_threshold));
}

SensorOctree::SensorOctree(const OctreeParams &params)
    : params_(params), tree_(std::make_unique<BoundedOcTree>(params.resolution)) {
    apply_params();
}

SensorOctree::SensorOctree(const OctreeParams &params, std::unique_ptr<BoundedOcTree> tree)
    : params_(params), tree_(std::move(tree)) {
    apply_params();
    // Inner nodes must hold the max of their children (OctoMap's binary
    // reader leaves the root at clamp_max; a .ot may be stale) and their
    // obstacle boxes, which no file carries.
    const BoundsScope scope(occupied_log_odds_);
    tree_->updateInnerOccupancy();
    recompute_known_bounds();
}

void SensorOctree::recompute_known_bounds() {
    known_bounds_ = Aabb();
    const TreeStats s = stats();
    if (s.has_known)
        known_bounds_ = Aabb{Vec3(s.known_min[0], s.known_min[1], s.known_min[2]),
                             Vec3(s.known_max[0], s.known_max[1], s.known_max[2])};
}

void SensorOctree::grow_known_bounds(const KeyBox &keys) {
    if (keys.empty) return;
    const double res = params_.resolution;
    Vec3 lo, hi;
    for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = (static_cast<double>(keys.lo[axis]) - kKeyCenter) * res;
        hi[axis] = (static_cast<double>(keys.hi[axis]) - kKeyCenter + 1) * res;
    }
    known_bounds_.grow(lo);
    known_bounds_.grow(hi);
}

SensorOctree::~SensorOctree() = default;

void SensorOctree::apply_params() {
    tree_->setProbHit(params_.prob_hit);
    tree_->setProbMiss(params_.prob_miss);
    tree_->setClampingThresMin(params_.clamp_min);
    tree_->setClampingThresMax(params_.clamp_max);
    tree_->setOccupancyThres(params_.occupied_threshold);
    occupied_log_odds_ = static_cast<float>(log_odds(params_.occupied_threshold));
    free_log_odds_ = static_cast<float>(log_odds(params_.free_threshold));
}

bool SensorOctree::contains(const Vec3 &point) const {
    // Reject far points before OctoMap converts them to int (undefined
    // behaviour for values beyond the int range).
    // The cube is [-limit, limit) on each axis (key 0 is the lower face).
    const double limit = kKeyCenter * params_.resolution;
    for (int axis = 0; axis < 3; ++axis)
        if (!(point[axis] >= -limit && point[axis] < limit)) return false;
    octomap::OcTreeKey key;
    return tree_->coordToKeyChecked(point.x(), point.y(), point.z(), key);
}

uint64_t SensorOctree::next_identity() {
    static std::atomic<uint64_t> counter{0};
    return ++counter;
}

void SensorOctree::clear() {
    ++generation_;
    tree_->clear();
    known_bounds_ = Aabb();
}

// Walks from the root towards the point's finest cell; stops at the leaf
// holding it, or at the first missing child (unknown space).
CellInfo SensorOctree::classify(const Vec3 &point) const {
    const octomap::OcTreeKey key = tree_->coordToKey(point.x(), point.y(), point.z());
    const OctreeView tree = view();
    CellKey cell;
    CellInfo info;
    OctreeView::NodeRef node = tree.root();
    while (node != nullptr && tree.has_children(node)) {
        const int shift = kTreeDepth - 1 - cell.depth;
        const int index = ((key[0] >> shift) & 1) | (((key[1] >> shift) & 1) << 1) |
                          (((key[2] >> shift) & 1) << 2);
        cell = cell.child(index);
        node = tree.child(node, index);
    }
    if (node != nullptr) {
        info.cell_class = classify_log_odds(tree.log_odds(node));
        info.probability = probability_from_log_odds(tree.log_odds(node));
    }
    for (int axis = 0; axis < 3; ++axis) info.center[axis] = cell.center(axis, params_.resolution);
    info.size = cell.size(params_.resolution);
    info.depth = cell.depth;
    return info;
}

namespace {
void grow_bounds(double lo[3], double hi[3], bool &has, const CellKey &cell, double resolution) {
    const double half = 0.5 * cell.size(resolution);
    for (int axis = 0; axis < 3; ++axis) {
        const double c = cell.center(axis, resolution);
        lo[axis] = has ? std::min(lo[axis], c - half) : c - half;
        hi[axis] = has ? std::max(hi[axis], c + half) : c + half;
    }
    has = true;
}
}  // namespace

TreeStats SensorOctree::stats() const {
    TreeStats s;
    const OctreeView tree = view();
    const double res = params_.resolution;
    if (OctreeView::NodeRef root = tree.root()) {
        traverse_nodes(
            tree, root, CellKey{},
            [&](OctreeView::NodeRef node, const CellKey &cell) {
                const int cls = classify_log_odds(tree.log_odds(node));
                ++s.leaves[cls];
                grow_bounds(s.known_min, s.known_max, s.has_known, cell, res);
                if (cls != kOccupied) return;
                grow_bounds(s.occupied_min, s.occupied_max, s.has_occupied, cell, res);
                if (extent::valid(tree.point_extent(node))) ++s.leaves_with_extent;
            },
            [&](OctreeView::NodeRef, const CellKey &) { ++s.inner_nodes; });
    }
    s.memory_bytes = tree_->memoryUsage();
    return s;
}

std::vector<uint32_t> SensorOctree::leaf_extents() const {
    std::vector<uint32_t> out;
    const OctreeView tree = view();
    for_each_leaf(tree, [&](OctreeView::NodeRef node, const CellKey &) { out.push_back(tree.point_extent(node)); });
    return out;
}

namespace {

// Depth first, children by index: the order of for_each_leaf.
void assign_extents(BoundedOcTree &tree, BoundedNode *node, const std::vector<uint32_t> &extents, size_t &next) {
    if (!tree.nodeHasChildren(node)) {
        node->set_point_extent(extents[next++]);
        return;
    }
    for (unsigned i = 0; i < 8; ++i)
        if (tree.nodeChildExists(node, i)) assign_extents(tree, tree.getNodeChild(node, i), extents, next);
}

}  // namespace

bool SensorOctree::set_leaf_extents(const std::vector<uint32_t> &extents) {
    size_t leaves = 0;
    for_each_leaf(view(), [&](OctreeView::NodeRef, const CellKey &) { ++leaves; });
    if (extents.size() != leaves) return false;
    size_t next = 0;
    if (tree_->getRoot() != nullptr) assign_extents(*tree_, tree_->getRoot(), extents, next);
    ++generation_;  // query contexts holding boxes of this map rebuild them
    return true;
}

}  // namespace octoprox
