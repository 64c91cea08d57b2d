#include "query/spheres/sphere_query.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "octree/octree_cell.hpp"

namespace octoprox {
namespace {

class SphereDescent {
public:
    SphereDescent(const OctreeView &view, const PlacedShape &sphere, const SphereSettings &settings)
        : view_(view), sphere_(sphere), settings_(settings) {
        model_.inner_boxes = !settings.unknown_occupied && settings.threshold_log_odds >= view.bounds_threshold();
        model_.point_extents = settings.point_extents;
        model_.threshold = settings.threshold_log_odds;
        model_.pad = obstacle_box_pad(view.resolution());
    }

    bool run() {
        OctreeCell cell = root_cell(view_);
        if (skip(cell) || !sphere_.box.overlaps(cell.box)) return false;
        // Down the levels where the sphere's box reaches one child alone:
        // the descent below would visit that child only.
        while (cell.node != nullptr && view_.has_children(cell.node)) {
            const Vec3 mid = mid_planes(cell, view_.resolution());
            const unsigned reached = children_overlapping(sphere_.box, mid);
            if ((reached & (reached - 1)) != 0) break;
            const int i = __builtin_ctz(reached);
            const OctreeCell child = child_cell(cell, view_.child(cell.node, i), i, mid);
            if (skip(child)) return false;
            cell = child;
        }
        return visit(cell);
    }

private:
    // As the direct engine's skip_child without cost: a subtree whose
    // maximum is below the threshold, or unknown space when it is free.
    bool skip(const OctreeCell &cell) const {
        if (settings_.unknown_occupied) return false;
        return cell.node == nullptr || view_.log_odds(cell.node) < settings_.threshold_log_odds;
    }

    bool touches_leaf(const OctreeCell &cell) const {
        if (cell.node != nullptr && view_.log_odds(cell.node) < settings_.threshold_log_odds) return false;
        const Aabb box = obstacle_bounds(view_, cell, model_, false);
        uint64_t tests = 0;
        return shape_touches_cell(sphere_, box.center(), box.half_extent(), tests);
    }

    // Recursion depth is bounded by kTreeDepth.
    bool visit(const OctreeCell &cell) const {
        if (cell.node == nullptr || !view_.has_children(cell.node)) return touches_leaf(cell);
        const Vec3 mid = mid_planes(cell, view_.resolution());
        const unsigned reached = children_overlapping(sphere_.box, mid);
        view_.prefetch_children(cell.node, reached);
        for (unsigned bits = reached; bits != 0; bits &= bits - 1) {
            const int i = __builtin_ctz(bits);
            const OctreeCell child = child_cell(cell, view_.child(cell.node, i), i, mid);
            if (skip(child)) continue;
            const Aabb bounds = obstacle_bounds(view_, child, model_);
            if (!sphere_.box.overlaps(bounds) || !shape_may_touch(sphere_, bounds)) continue;
            if (visit(child)) return true;
        }
        return false;
    }

    const OctreeView &view_;
    const PlacedShape &sphere_;
    const SphereSettings &settings_;
    ObstacleModel model_;
};

}  // namespace

bool sphere_collides(const SensorOctree &tree, const Vec3 &center, double radius, const SphereSettings &settings) {
    // One placed sphere a thread, reused: a PlacedShape is too large to
    // build per call.
    thread_local PlacedShape sphere;
    sphere.kind = ShapeKind::kSphere;
    sphere.inflation = radius;
    sphere.core.kind = ConvexKind::kPoint;
    sphere.core.center = center;
    sphere.box = Aabb::from_center(center, Vec3::Constant(radius));
    const OctreeView view = tree.view();
    return SphereDescent(view, sphere, settings).run();
}

}  // namespace octoprox
