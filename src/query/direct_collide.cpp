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
    outcome_ = CollisionOutcome();
    done_ = false;
    if (!links.tree().empty()) {
        const Cell root{view.root(), CellKey{}};
        // An empty map is one unknown cube.
        if (root.node != nullptr || settings.unknown_occupied) recurse(root, links.tree().root());
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

// Children below the threshold hold no obstacle (an inner node keeps the
// maximum log-odds of its subtree) unless unknown space counts as occupied:
// then only observed-free leaves can be skipped, at the leaf test.
void DirectCollider::descend_octree(const Cell &cell, int32_t robot_node) {
    for (int i = 0; i < 8 && !done_; ++i) {
        const Cell child{view_->child(cell.node, i), cell.key.child(i)};
        if (child.node == nullptr) {
            if (settings_.unknown_occupied) recurse(child, robot_node);
            continue;
        }
        if (!settings_.unknown_occupied && view_->log_odds(child.node) < settings_.threshold_log_odds)
            continue;
        recurse(child, robot_node);
    }
}

bool DirectCollider::is_obstacle_leaf(const Cell &cell) const {
    if (cell.node == nullptr) return settings_.unknown_occupied;
    return view_->log_odds(cell.node) >= settings_.threshold_log_odds;
}

void DirectCollider::test_leaf_pair(const Cell &cell, int32_t robot_node) {
    if (!is_obstacle_leaf(cell)) return;
    const PlacedShape &shape = links_->placed()[links_->tree().node(robot_node).item];
    if (shape.box.empty()) return;  // a disabled link
    const double resolution = view_->resolution();
    const Vec3 center(cell.key.center(0, resolution), cell.key.center(1, resolution),
                      cell.key.center(2, resolution));
    const Vec3 half = Vec3::Constant(0.5 * cell.key.size(resolution));
    if (shape_touches_cell(shape, center, half, outcome_.narrow_tests)) record(cell, shape);
}

void DirectCollider::record(const Cell &cell, const PlacedShape &shape) {
    outcome_.collided = true;
    if (contacts_->size() >= settings_.max_contacts) {
        // One contact more than asked for: the list is incomplete.
        outcome_.truncated = settings_.max_contacts > 0 || outcome_.truncated;
        done_ = true;
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
    if (contacts_->size() >= settings_.max_contacts && settings_.max_contacts <= 1) done_ = true;
}

}  // namespace octoprox
