#include "query/direct/direct_collide.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "octree/cube_entry.hpp"

namespace octoprox {

CollisionOutcome DirectCollider::collide(const SensorOctree &tree, const LinkSet &links,
                                         const CollisionSettings &settings,
                                         std::vector<Contact> &contacts) {
    const OctreeView view = tree.view();
    view_ = &view, tree_ = &tree, links_ = &links, settings_ = settings;
    outcome_ = CollisionOutcome();
    ContactSink sink(settings_, contacts, outcome_);
    contacts_ = &sink;
    cost_.clear();
    done_ = false;
    model_.inner_boxes = !settings.unknown_occupied && !settings.cost &&
                         settings.threshold_log_odds >= view.bounds_threshold();
    model_.point_extents = settings.point_extents;
    model_.threshold = settings.threshold_log_odds;
    model_.pad = obstacle_box_pad(view.resolution());
    if (!links.tree().empty()) {
        if (settings.max_contacts == 0 && !settings.unknown_occupied && !settings.cost) {
            enter_at_cubes(view);
        } else {
            const Cell root = root_cell(view);
            // An empty map is one unknown cube.
            if ((root.node != nullptr || !skip_child(root)) &&
                links.tree().node(links.tree().root()).box.overlaps(root.box))
                recurse(root, links.tree().root());
        }
    }
    view_ = nullptr, contacts_ = nullptr;
    return outcome_;
}

// A yes or no with unknown space free: the descent starts at the cubes,
// about as wide as the robot, that its box overlaps (cube_entry.hpp), found
// by their keys, instead of bounding the robot against every cube above
// them (a dozen levels, in each octant the robot spans).  The descent
// below prunes the same way, so the answer is the same; only the order of
// the contacts found could differ, and none is kept.
void DirectCollider::enter_at_cubes(const OctreeView &view) {
    const int32_t robot_root = links_->tree().root();
    const Aabb &robot_box = links_->tree().node(robot_root).box;
    CubeEntries entries;
    CubeEntryFinder(view).find(robot_box, settings_.threshold_log_odds, model_.inner_boxes, entries);
    for (int k = 0; k < entries.count && !done_; ++k)
        if (robot_box.overlaps(bounding_box(entries.cells[k]))) recurse(entries.cells[k], robot_root);
}

// Algorithm 1: descend the larger of the two nodes (both measured by their
// longest edge), test leaf pairs exactly.  Boxes are tested before a call,
// so every call has an overlapping pair.
void DirectCollider::recurse(const Cell &cell, int32_t robot_node) {
    if (done_) return;
    const AabbTree &tree = links_->tree();
    const AabbTreeNode &robot = tree.node(robot_node);
    const bool octree_leaf = cell.node == nullptr || !view_->has_children(cell.node);
    if (octree_leaf && robot.is_leaf()) return test_leaf_pair(cell, robot_node);
    // Descending the robot splits one box into two; descending the octree
    // splits one cube into eight, each half as wide: favour the robot until
    // the cube is twice the robot node's size (measured: fewer visits).
    if (robot.is_leaf() || (!octree_leaf && cell.box.hi.x() - cell.box.lo.x() > 2.0 * robot.box.longest_edge()))
        return descend_octree(cell, robot_node);
    const Aabb cell_bound = bounding_box(cell);
    if (tree.node(robot.left).box.overlaps(cell_bound)) recurse(cell, robot.left);
    if (tree.node(robot.right).box.overlaps(cell_bound)) recurse(cell, robot.right);
}

// Only the children the robot node's box reaches, skipping those that hold
// nothing the query looks for.
void DirectCollider::descend_octree(const Cell &cell, int32_t robot_node) {
    const AabbTreeNode &robot = links_->tree().node(robot_node);
    const Vec3 mid = mid_planes(cell, view_->resolution());
    const unsigned reached = children_overlapping(robot.box, mid);
    // A single shape is culled by its own tighter test, not only its box.
    const PlacedShape *shape = robot.is_leaf() ? &links_->placed()[robot.item] : nullptr;
    view_->prefetch_children(cell.node, reached);
    for (unsigned bits = reached; bits != 0 && !done_; bits &= bits - 1) {
        const int i = __builtin_ctz(bits);
        const Cell child = child_cell(cell, view_->child(cell.node, i), i, mid);
        if (skip_child(child)) continue;
        const Aabb child_bound = bounding_box(child);
        if (!robot.box.overlaps(child_bound)) continue;
        if (shape != nullptr && !shape_may_touch(*shape, child_bound)) continue;
        recurse(child, robot_node);
    }
}

// Which octree children can hold nothing the query looks for.  An inner
// node keeps the maximum log-odds of its subtree, so a subtree below the
// threshold holds no obstacle; unknown space (missing children) matters
// only when it is occupied, or, for cost, inside the region.
bool DirectCollider::skip_child(const Cell &child) const {
    if (settings_.unknown_occupied) return false;
    const bool in_region = settings_.cost && settings_.region.overlaps(child.box);
    if (child.node == nullptr) return !in_region;
    const float l = view_->log_odds(child.node);
    if (l >= settings_.threshold_log_odds) return false;
    if (!settings_.cost) return true;
    return l < settings_.free_log_odds && !in_region;
}


void DirectCollider::test_leaf_pair(const Cell &cell, int32_t robot_node) {
    const PlacedShape &shape = links_->placed()[links_->tree().node(robot_node).item];
    if (shape.box.empty()) return;  // a disabled link
    if (cell.node == nullptr) {
        if (settings_.unknown_occupied) test_obstacle(cell, shape);
        else if (settings_.cost) test_cost(cell, shape);
        return;
    }
    const float l = view_->log_odds(cell.node);
    if (l >= settings_.threshold_log_odds) test_obstacle(cell, shape);
    else if (settings_.cost && l >= settings_.free_log_odds) test_cost(cell, shape);
}

// Once the obstacle answer is settled, a plain query is done; a cost query
// goes on for the cost.
void DirectCollider::test_obstacle(const Cell &cell, const PlacedShape &shape) {
    const bool unknown = cell.node == nullptr;
    const bool settled = contacts_->offer(shape, bounding_box(cell), [&] {
        return describe_cell(*tree_, cell.key, unknown, unknown ? 0.0f : view_->log_odds(cell.node));
    });
    if (settled) done_ = !settings_.cost;
}

void DirectCollider::test_cost(const Cell &cell, const PlacedShape &shape) {
    const bool unknown = cell.node == nullptr;
    cost_.offer(shape, cell.key, unknown, unknown ? 0.0f : view_->log_odds(cell.node), cell.box, settings_,
                outcome_.narrow_tests);
}

}  // namespace octoprox
