#include "query/direct_collide.hpp"

#include "query/narrow_phase.hpp"

namespace octoprox {
namespace {

Aabb cell_box(const CellKey &key, double resolution) {
    const double half = 0.5 * key.size(resolution);
    const Vec3 center(key.center(0, resolution), key.center(1, resolution), key.center(2, resolution));
    return Aabb::from_center(center, Vec3::Constant(half));
}

}  // namespace

CollisionOutcome DirectCollider::collide(const SensorOctree &tree, const LinkSet &links,
                                         const CollisionSettings &settings,
                                         std::vector<Contact> &contacts) {
    const OctreeView view = tree.view();
    view_ = &view, tree_ = &tree, links_ = &links, settings_ = settings, contacts_ = &contacts;
    contacts.clear();
    cost_.clear();
    outcome_ = CollisionOutcome();
    done_ = false;
    obstacles_settled_ = false;
    if (!links.tree().empty()) {
        const Cell root{view.root(), CellKey{}};
        // An empty map is one unknown cube.
        if (root.node != nullptr || !skip_child(root)) recurse(root, links.tree().root());
    }
    view_ = nullptr;
    return outcome_;
}

// Algorithm 1: prune by box overlap, descend the larger of the two nodes
// (both measured by their longest edge), test leaf pairs exactly.
void DirectCollider::recurse(const Cell &cell, int32_t robot_node) {
    if (done_) return;
    const AabbTreeNode &robot = links_->tree().node(robot_node);
    const double resolution = view_->resolution();
    if (!robot.box.overlaps(cell_box(cell.key, resolution))) return;
    const bool octree_leaf = cell.node == nullptr || !view_->has_children(cell.node);
    if (octree_leaf && robot.is_leaf()) return test_leaf_pair(cell, robot_node);
    if (robot.is_leaf() || (!octree_leaf && cell.key.size(resolution) > robot.box.longest_edge()))
        return descend_octree(cell, robot_node);
    recurse(cell, robot.left);
    recurse(cell, robot.right);
}

// Which octree children can hold nothing the query looks for.  An inner
// node keeps the maximum log-odds of its subtree, so a subtree below the
// threshold holds no obstacle; unknown space (missing children) matters
// only when it is occupied, or, for cost, inside the region.
bool DirectCollider::skip_child(const Cell &child) const {
    if (settings_.unknown_occupied) return false;
    const bool in_region = settings_.cost && settings_.region.overlaps(cell_box(child.key, view_->resolution()));
    if (child.node == nullptr) return !in_region;
    const float l = view_->log_odds(child.node);
    if (l >= settings_.threshold_log_odds) return false;
    if (!settings_.cost) return true;
    return l < settings_.free_log_odds && !in_region;
}

void DirectCollider::descend_octree(const Cell &cell, int32_t robot_node) {
    for (int i = 0; i < 8 && !done_; ++i) {
        const Cell child{view_->child(cell.node, i), cell.key.child(i)};
        if (!skip_child(child)) recurse(child, robot_node);
    }
}

void DirectCollider::test_leaf_pair(const Cell &cell, int32_t robot_node) {
    const PlacedShape &shape = links_->placed()[links_->tree().node(robot_node).item];
    if (shape.box.empty()) return;  // a disabled link
    const Aabb box = cell_box(cell.key, view_->resolution());
    if (cell.node == nullptr) {
        if (settings_.unknown_occupied) test_obstacle(cell, shape, box);
        else if (settings_.cost) test_cost(cell, shape, box);
        return;
    }
    const float l = view_->log_odds(cell.node);
    if (l >= settings_.threshold_log_odds) test_obstacle(cell, shape, box);
    else if (settings_.cost && l >= settings_.free_log_odds) test_cost(cell, shape, box);
}

void DirectCollider::settle_obstacles() {
    obstacles_settled_ = true;
    done_ = !settings_.cost;
}

void DirectCollider::test_obstacle(const Cell &cell, const PlacedShape &shape, const Aabb &box) {
    if (obstacles_settled_) return;
    if (shape_touches_cell(shape, box.center(), box.half_extent(), outcome_.narrow_tests)) record(cell, shape);
}

// Unknown space counts only inside the region; uncertain cells wholly.
void DirectCollider::test_cost(const Cell &cell, const PlacedShape &shape, const Aabb &box) {
    const bool unknown = cell.node == nullptr;
    const Aabb region = unknown ? Aabb{box.lo.cwiseMax(settings_.region.lo), box.hi.cwiseMin(settings_.region.hi)} : box;
    if (region.empty() || !(region.lo.array() <= region.hi.array()).all()) return;
    if (!shape_touches_cell(shape, region.center(), region.half_extent(), outcome_.narrow_tests)) return;
    const double p = unknown ? settings_.unknown_probability : probability_from_log_odds(view_->log_odds(cell.node));
    cost_.add(shape.link, cell.key, unknown ? kUnknown : kUncertain, p, region);
}

// Contacts up to max_contacts; one more found means the list is
// incomplete (truncated).  Once the obstacle answer is settled, a plain
// query is done; a cost query goes on for the cost.
void DirectCollider::record(const Cell &cell, const PlacedShape &shape) {
    outcome_.collided = true;
    if (contacts_->size() >= settings_.max_contacts) {
        outcome_.truncated = settings_.max_contacts > 0;
        settle_obstacles();
        return;
    }
    Contact c;
    c.link = shape.link, c.shape = shape.shape;
    const double resolution = view_->resolution();
    for (int axis = 0; axis < 3; ++axis) c.center[axis] = cell.key.center(axis, resolution);
    c.size = cell.key.size(resolution);
    if (cell.node == nullptr) {
        c.cell_class = kUnknown;
        c.probability = 0.5;
    } else {
        c.cell_class = tree_->classify_log_odds(view_->log_odds(cell.node));
        c.probability = probability_from_log_odds(view_->log_odds(cell.node));
    }
    contacts_->push_back(c);
    if (contacts_->size() >= settings_.max_contacts && settings_.max_contacts <= 1) settle_obstacles();
}

}  // namespace octoprox
