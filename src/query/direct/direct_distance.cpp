#include "query/direct/direct_distance.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "octree/cube_entry.hpp"
#include "query/cell_description.hpp"
#include "query/nearest_pair.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {

// Box distance, tightened by the shape itself when the node is one shape.
// A pair the boxes already put beyond the bound returns that distance
// (pruned by can_prune) without the square root or the shape's own test.
double DirectDistance::lower_bound(const AabbTreeNode &robot, const Aabb &cell) const {
    const double squared = robot.box.squared_distance(cell);
    if (bound_ > 1e-100 && squared >= bound_ * bound_) return bound_;  // no underflow
    const double boxes = std::sqrt(squared);
    if (!robot.is_leaf()) return boxes;
    return std::max(boxes, shape_lower_bound(placed_[robot.item], cell));
}

double DirectDistance::box_lower_bound(const AabbTreeNode &robot, const Aabb &cell) const {
    return std::sqrt(robot.box.squared_distance(cell));
}

void DirectDistance::start(const SensorOctree &tree, const LinkSet &links, const DistanceSettings &settings) {
    links_ = &links, settings_ = settings;
    robot_ = links.tree().nodes(), placed_ = links.placed().data();
    best_ = DistanceOutcome();
    set_bound(settings.cutoff);
    // The boxes hold the leaves at or above the map's threshold: a query
    // with a higher threshold has fewer obstacles, a lower one more.
    model_.inner_boxes = !settings.unknown_occupied && settings.threshold_log_odds >= view_->bounds_threshold();
    model_.point_extents = settings.point_extents;
    model_.threshold = settings.threshold_log_odds;
    model_.pad = obstacle_box_pad(view_->resolution());
    (void)tree;
}

DistanceOutcome DirectDistance::run(const SensorOctree &tree, const LinkSet &links,
                                    const DistanceSettings &settings) {
    const OctreeView view = tree.view();
    view_ = &view;
    start(tree, links, settings);
    only_link_ = -1;
    if (!links.tree().empty()) search_shapes();
    view_ = nullptr;
    return best_;
}

// Per link: one search per link, each bounded by that link's own best, so
// no link's minimum is pruned away by another link's.
DistanceOutcome DirectDistance::run_per_link(const SensorOctree &tree, const LinkSet &links,
                                             const DistanceSettings &settings,
                                             std::vector<double> &per_link) {
    const OctreeView view = tree.view();
    view_ = &view;
    per_link.assign(links.link_count(), std::numeric_limits<double>::infinity());
    DistanceOutcome overall;
    uint64_t tests = 0;
    DistanceSettings own = settings;
    for (uint32_t link = 0; link < links.link_count(); ++link) {
        if (settings.link_cutoffs != nullptr) {
            own.cutoff = std::min(settings.cutoff, (*settings.link_cutoffs)[link]);
            if (own.cutoff < 0.0) continue;
        }
        start(tree, links, own);
        only_link_ = static_cast<int32_t>(link);
        if (!links.tree().empty()) search_shapes();
        tests += best_.narrow_tests;
        if (best_.found) per_link[link] = best_.distance;
        if (best_.found && (!overall.found || best_.distance < overall.distance)) overall = best_;
    }
    overall.narrow_tests = tests;
    view_ = nullptr;
    return overall;
}

void DirectDistance::search(int32_t robot_node) {
    const Cell root = root_cell(*view_);
    if (root.node == nullptr && !settings_.unknown_occupied) return;
    const bool inner = is_inner(*view_, root);
    const Aabb bounds = bounding_box(root, inner);
    recurse(root, bounds, inner, robot_node, lower_bound(robot_[robot_node], bounds));
}

// Shape by shape, each entering the octree at the cubes its reach (its box
// grown by the bound) overlaps, found from their keys (cube_entry.hpp):
// no robot tree walks the octree's upper levels, where every shape would
// be bounded against cube after cube only to enter each of them.
//
// A shape's reach needs a finite bound, and a loose one costs: the search
// runs in rounds with a growing radius as the bound, starting at a cell
// (or at the gap between the robot's box and the map's obstacles).  Pairs
// nearer than the radius are never pruned, so the first round that finds
// a pair has found the minimum; the rounds before it cost little, their
// reach being small.  With unknown space as obstacle, cubes of unknown
// space have no node to enter by: the robot tree walks the octree instead.
void DirectDistance::search_shapes() {
    const int32_t robot_root = links_->tree().root();
    if (settings_.unknown_occupied) return search(robot_root);
    const OctreeView::NodeRef root = view_->root();
    if (root == nullptr) return;
    CubeEntryFinder entries(*view_);
    const Aabb map_bounds = bounding_box(root_cell(*view_), view_->has_children(root));
    const double robot_gap = std::sqrt(robot_[robot_root].box.squared_distance(map_bounds));
    const double largest = 4.0 * kKeyCenter * view_->resolution();  // beyond the map cube's diagonal
    for (double radius = std::max(view_->resolution(), robot_gap + view_->resolution());; radius *= kRadiusGrowth) {
        const bool last = !(radius < settings_.cutoff) || radius > largest;
        set_bound(last ? settings_.cutoff : radius);
        search_round(entries);
        if (best_.found || last) break;
    }
}

namespace {

// Each shape's leaf node, and then the first 160 bytes of its
// PlacedShape (shape.hpp: kind, inflation, core, what its lower bounds
// read), are asked for ahead of the shape, in two steps: the leaf 8
// shapes ahead, and the shape 4 ahead from that leaf, by then in cache.
// Their misses then overlap the work on the shapes before them instead
// of stalling it one by one.
constexpr size_t kLeafPrefetchAhead = 8;
constexpr size_t kShapePrefetchAhead = 4;
constexpr size_t kShapeHotBytes = 160;

void prefetch_shape(const PlacedShape &shape) {
    const char *bytes = reinterpret_cast<const char *>(&shape);
    for (size_t offset = 0; offset < kShapeHotBytes + 63; offset += 64) __builtin_prefetch(bytes + offset);
}

}  // namespace

// Every shape once, in the robot tree's order (neighbours one after the
// other), from the tree's list of its leaves: no inner node is read.
void DirectDistance::search_round(CubeEntryFinder &entries) {
    const std::vector<int32_t> &leaves = links_->tree().leaves();
    for (size_t k = 0; k < leaves.size(); ++k) {
        const int32_t index = leaves[k];
        const AabbTreeNode &leaf = robot_[index];
        if (k + kLeafPrefetchAhead < leaves.size()) __builtin_prefetch(&robot_[leaves[k + kLeafPrefetchAhead]]);
        if (k + kShapePrefetchAhead < leaves.size()) prefetch_shape(placed_[robot_[leaves[k + kShapePrefetchAhead]].item]);
        if (leaf.box.empty()) continue;  // a leaf's box is its shape's: empty when disabled
        if (only_link_ >= 0 && placed_[leaf.item].link != static_cast<uint32_t>(only_link_)) continue;
        if (!settings_.signed_distance && best_.found && bound_ <= 0.0) return;  // in contact: nothing is nearer
        // Unbounded (the last round without a cutoff) until a first pair is
        // found, or signed and in contact: from the root.
        if (std::isfinite(bound_) && bound_ > 0.0) search_shape_from_entries(entries, index);
        else search(index);
    }
}

void DirectDistance::search_shape_from_entries(CubeEntryFinder &finder, int32_t leaf) {
    const AabbTreeNode &robot = robot_[leaf];
    Aabb reach = robot.box;
    reach.inflate(bound_);
    CubeEntries &entries = entries_;
    finder.find(reach, settings_.threshold_log_odds, model_.inner_boxes, entries);
    double lower[8];
    Aabb *bounds = entry_bounds_;
    bool inner[8];
    int order[8];
    int count = 0;
    for (int k = 0; k < entries.count; ++k) {
        inner[k] = view_->has_children(entries.cells[k].node);
        bounds[k] = bounding_box(entries.cells[k], inner[k]);
        lower[k] = lower_bound(robot, bounds[k]);
        if (can_prune(lower[k])) continue;
        int at = count;
        for (; at > 0 && lower[order[at - 1]] > lower[k]; --at) order[at] = order[at - 1];
        order[at] = k, ++count;
    }
    for (int j = 0; j < count; ++j) {
        const int k = order[j];
        recurse(entries.cells[k], bounds[k], inner[k], leaf, lower[k]);
    }
}

// The bound, and what can_prune derives from it and from the best pair.
void DirectDistance::set_bound(double bound) {
    bound_ = bound;
    in_contact_ = settings_.signed_distance && bound_ <= 0.0;
    slack_ = best_.found ? std::max(settings_.abs_err, settings_.rel_err * best_.distance) : 0.0;
}

bool DirectDistance::is_obstacle(const Cell &cell) const {
    if (cell.node == nullptr) return settings_.unknown_occupied;
    return view_->log_odds(cell.node) >= settings_.threshold_log_odds;
}

void DirectDistance::recurse(const Cell &cell, const Aabb &bounds, bool inner, int32_t robot_node, double lower) {
    if (can_prune(lower)) return;
    const AabbTreeNode &robot = robot_[robot_node];
    const bool octree_leaf = !inner;
    if (octree_leaf && robot.is_leaf()) return test_leaf_pair(cell, bounds, robot);
    // As in collision: favour the robot until the cube is twice its node.
    if (robot.is_leaf() || (!octree_leaf && cell.box.hi.x() - cell.box.lo.x() > 2.0 * robot.box.longest_edge()))
        return descend_octree(cell, robot_node);
    // Nearer robot child first, by their boxes alone: a shape's own bound
    // here, against a cell still larger than the robot node, rarely prunes
    // what the descent below would not, and cost 6% of a scene F query.
    int32_t first = robot.left, second = robot.right;
    double lower_first = box_lower_bound(robot_[first], bounds), lower_second = box_lower_bound(robot_[second], bounds);
    if (lower_second < lower_first) std::swap(first, second), std::swap(lower_first, lower_second);
    recurse(cell, bounds, inner, first, lower_first);
    recurse(cell, bounds, inner, second, lower_second);
}

// Only the children within the current bound of the robot node's box,
// without obstacles skipped (max log-odds below the threshold, or unknown
// when unknown is free), nearest first by their lower bounds.
void DirectDistance::descend_octree(const Cell &cell, int32_t robot_node) {
    const AabbTreeNode &robot = robot_[robot_node];
    Aabb reach = robot.box;
    if (std::isfinite(bound_)) reach.inflate(std::max(bound_, 0.0));
    const Vec3 mid = mid_planes(cell, view_->resolution());
    const unsigned reached = std::isfinite(bound_) ? children_overlapping(reach, mid) : 0xFFu;
    Child children[8];
    int order[8];  // indices into children, nearest first
    int count = 0;
    view_->prefetch_children(cell.node, reached);
    for (unsigned bits = reached; bits != 0; bits &= bits - 1) {
        const int i = __builtin_ctz(bits);
        // Where unknown is free, an absent child reads as a leaf below any
        // threshold: no pointer to read.
        const OctreeView::NodeRef node =
            settings_.unknown_occupied ? view_->child(cell.node, i) : view_->child_or_absent(cell.node, i);
        if (node == nullptr ? !settings_.unknown_occupied
                            : (!settings_.unknown_occupied && view_->log_odds(node) < settings_.threshold_log_odds))
            continue;
        const bool inner = node != nullptr && view_->has_children(node);
        const Aabb bounds = obstacle_bounds(*view_, node, child_box(cell.box, i, mid), model_, inner);
        const double lower = lower_bound(robot, bounds);
        if (can_prune(lower)) continue;
        if (inner) view_->prefetch_children(node, 0xFFu);  // most survivors are descended
        children[count] = Child{node, lower, i, inner, bounds.lo, bounds.hi};
        // Insertion sort of indices: at most 8 children.
        int at = count;
        for (; at > 0 && children[order[at - 1]].lower > lower; --at) order[at] = order[at - 1];
        order[at] = count++;
    }
    for (int k = 0; k < count; ++k) {
        const Child &next = children[order[k]];
        if (can_prune(next.lower)) continue;  // a nearer sibling lowered the bound
        const Cell child = child_cell(cell, next.node, next.index, mid);
        recurse(child, Aabb{next.bounds_lo, next.bounds_hi}, next.inner, robot_node, next.lower);
    }
}

void DirectDistance::test_leaf_pair(const Cell &cell, const Aabb &box, const AabbTreeNode &robot) {
    if (!is_obstacle(cell)) return;
    const PlacedShape &shape = placed_[robot.item];
    if (shape.box.empty()) return;  // a disabled link
    if (only_link_ >= 0 && shape.link != static_cast<uint32_t>(only_link_)) return;
    // The bound is the best pair's distance once one is found: a pair below
    // it is the new best.
    ShapeCellDistance d;
    if (!nearer_pair(shape, box, bound_, settings_.signed_distance, d, best_.narrow_tests)) return;
    if (!keep_if_nearer(shape, d, best_)) return;
    const bool unknown = cell.node == nullptr;
    set_cell(best_, cell.key, unknown, unknown ? 0.0f : view_->log_odds(cell.node));
    set_bound(d.distance);
}

}  // namespace octoprox
