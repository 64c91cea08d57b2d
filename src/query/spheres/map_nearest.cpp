#include "query/spheres/map_nearest.hpp"

#include "octree/octree_cell.hpp"
#include "octree/point_extent.hpp"

namespace octoprox {
namespace {

struct Child {
    double squared;
    OctreeCell cell;
};

// The children of an inner cell whose bound is nearer than the best, in
// order of that bound (ties by index); `bound(child)` gives the box
// bounding a child's pieces, or an empty box to leave the child out.
template <class Bound>
int near_children(const OctreeView &view, const OctreeCell &cell, const Vec3 &at, double best, Bound &&bound,
                  Child out[8]) {
    const Vec3 mid = mid_planes(cell, view.resolution());
    int n = 0;
    for (int i = 0; i < 8; ++i) {
        const OctreeCell child = child_cell(cell, view.child(cell.node, i), i, mid);
        const Aabb box = bound(child);
        if (box.empty()) continue;
        const double squared = squared_to(at, box);
        if (!(squared < best)) continue;
        int j = n++;
        for (; j > 0 && out[j - 1].squared > squared; --j) out[j] = out[j - 1];
        out[j] = Child{squared, child};
    }
    return n;
}

class ObstacleSearch {
public:
    ObstacleSearch(const OctreeView &view, const Vec3 &at, const SphereSettings &settings)
        : view_(view), at_(at), settings_(settings) {
        model_.inner_boxes = !settings.unknown_occupied && settings.threshold_log_odds >= view.bounds_threshold();
        model_.point_extents = settings.point_extents;
        model_.threshold = settings.threshold_log_odds;
        model_.pad = obstacle_box_pad(view.resolution());
    }

    // Recursion depth is bounded by kTreeDepth.
    void visit(const OctreeCell &cell, NearestPiece &best) const {
        if (cell.node == nullptr || !view_.has_children(cell.node)) {
            if (obstacle_leaf(cell.node)) best.offer(at_, leaf_obstacle_box(view_, cell.node, cell.box, settings_));
            return;
        }
        Child near[8];
        const int n = near_children(view_, cell, at_, best.squared, [&](const OctreeCell &child) {
            return skipped(child.node) ? Aabb{} : obstacle_bounds(view_, child, model_);
        }, near);
        for (int k = 0; k < n; ++k)
            if (near[k].squared < best.squared) visit(near[k].cell, best);
    }

    bool skipped(OctreeView::NodeRef node) const {
        if (settings_.unknown_occupied) return false;
        return node == nullptr || view_.log_odds(node) < settings_.threshold_log_odds;
    }

private:
    bool obstacle_leaf(OctreeView::NodeRef node) const {
        if (node == nullptr) return settings_.unknown_occupied;
        return view_.log_odds(node) >= settings_.threshold_log_odds;
    }

    const OctreeView &view_;
    const Vec3 &at_;
    const SphereSettings &settings_;
    ObstacleModel model_;
};

class FreeSearch {
public:
    FreeSearch(const OctreeView &view, const Vec3 &at, const SphereSettings &settings)
        : view_(view), at_(at), settings_(settings) {}

    void visit(const OctreeCell &cell, NearestPiece &best) const {
        const OctreeView::NodeRef node = cell.node;
        if (node == nullptr) {
            if (!settings_.unknown_occupied) best.offer(at_, cell.box);
            return;
        }
        const bool below = view_.log_odds(node) < settings_.threshold_log_odds;
        if (!view_.has_children(node)) {
            if (below) best.offer(at_, cell.box);
            else if (settings_.point_extents) offer_outside_extent(cell, best);
            return;
        }
        // An inner node's log-odds is its children's maximum: below the
        // threshold, its whole cube is free (unknown parts too, when free).
        if (below && !settings_.unknown_occupied) {
            best.offer(at_, cell.box);
            return;
        }
        Child near[8];
        const int n = near_children(view_, cell, at_, best.squared, [](const OctreeCell &child) { return child.box; },
                                    near);
        for (int k = 0; k < n; ++k)
            if (near[k].squared < best.squared) visit(near[k].cell, best);
    }

private:
    // An obstacle leaf's cube outside its extent: up to six slabs, one
    // per face of the extent that lies inside the cube.
    void offer_outside_extent(const OctreeCell &cell, NearestPiece &best) const {
        const Aabb box = leaf_obstacle_box(view_, cell.node, cell.box, settings_);
        for (int axis = 0; axis < 3; ++axis) {
            if (box.lo[axis] > cell.box.lo[axis]) {
                Aabb slab = cell.box;
                slab.hi[axis] = box.lo[axis];
                best.offer(at_, slab);
            }
            if (box.hi[axis] < cell.box.hi[axis]) {
                Aabb slab = cell.box;
                slab.lo[axis] = box.hi[axis];
                best.offer(at_, slab);
            }
        }
    }

    const OctreeView &view_;
    const Vec3 &at_;
    const SphereSettings &settings_;
};

}  // namespace

Aabb leaf_obstacle_box(const OctreeView &view, OctreeView::NodeRef node, const Aabb &cube,
                       const SphereSettings &settings) {
    if (!settings.point_extents || node == nullptr) return cube;
    const uint32_t packed = view.point_extent(node);
    if (packed == 0) return cube;
    // Slot planes exactly as obstacle_box places them, without its pad;
    // an extent reaching a face of the cube takes that face itself.
    Aabb box = cube;
    const double slot = (cube.hi.x() - cube.lo.x()) * (1.0 / extent::kSlots);
    for (int axis = 0; axis < 3; ++axis) {
        const int lo = extent::lo(packed, axis), hi = extent::hi(packed, axis);
        if (lo > 0) box.lo[axis] = cube.lo[axis] + slot * lo;
        if (hi < extent::kSlots - 1) box.hi[axis] = cube.lo[axis] + slot * (hi + 1);
    }
    return box;
}

NearestPiece nearest_obstacle(const OctreeView &view, const Vec3 &at, double bound_squared,
                              const SphereSettings &settings) {
    NearestPiece best;
    best.squared = bound_squared;
    const ObstacleSearch search(view, at, settings);
    const OctreeCell root = root_cell(view);
    if (!search.skipped(root.node)) search.visit(root, best);
    return best;
}

NearestPiece nearest_free(const OctreeView &view, const Vec3 &at, const SphereSettings &settings) {
    NearestPiece best;
    const OctreeCell root = root_cell(view);
    // Beyond the map cube is free: its nearest point first.
    Aabb cube = root.box;
    if ((at.array() < cube.lo.array()).any() || (at.array() > cube.hi.array()).any()) {
        best.found = true, best.squared = 0.0, best.point = at;
        best.box = Aabb{at, at};
        return best;
    }
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const double face = side == 0 ? cube.lo[axis] : cube.hi[axis];
            Aabb outside{at, at};
            outside.lo[axis] = outside.hi[axis] = face;
            best.offer(at, outside);
        }
    FreeSearch(view, at, settings).visit(root, best);
    return best;
}

}  // namespace octoprox
