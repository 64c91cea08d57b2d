#include "query/spheres/sphere_query.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "octree/octree_cell.hpp"
#include "query/spheres/sphere_grid.hpp"

#include <cmath>

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
        if (!down_by_keys(cell)) return false;
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
    // The first levels of the descent below, from keys instead of boxes:
    // down to the deepest cube holding every cell the sphere's box might
    // reach (its keys widened by a cell on each side, so rounding never
    // leaves one out), the child holding them is the only one the box
    // overlaps.  False when a cube on the way is skipped (no collision).
    bool down_by_keys(OctreeCell &cell) const {
        uint32_t lo[3], hi[3];
        if (!widened_keys(lo, hi)) return true;  // at the map's faces: the boxes decide
        int depth = 0;  // the levels lo and hi share
        while (depth < kTreeDepth) {
            const int bit = kTreeDepth - 1 - depth;
            if (((lo[0] ^ hi[0]) | (lo[1] ^ hi[1]) | (lo[2] ^ hi[2])) >> bit) break;
            ++depth;
        }
        CellKey key;
        OctreeView::NodeRef node = cell.node;
        for (int d = 0; d < depth && node != nullptr && view_.has_children(node); ++d) {
            const int bit = kTreeDepth - 1 - d;
            const int i = static_cast<int>(((lo[0] >> bit) & 1) | (((lo[1] >> bit) & 1) << 1) | (((lo[2] >> bit) & 1) << 2));
            node = view_.child(node, i);
            key = key.child(i);
            if (skipped(node)) return false;
        }
        if (key.depth > 0) cell = OctreeCell{node, key, cell_box(key, view_.resolution())};
        return true;
    }

    // The keys of the cells holding the sphere box's corners, one more on
    // each side; false when they leave the map's keys.
    bool widened_keys(uint32_t lo[3], uint32_t hi[3]) const {
        const double per_cell = 1.0 / view_.resolution();
        for (int axis = 0; axis < 3; ++axis) {
            const double low = std::floor(sphere_.box.lo[axis] * per_cell) + kKeyCenter - 1.0;
            const double high = std::floor(sphere_.box.hi[axis] * per_cell) + kKeyCenter + 1.0;
            if (!(low >= 0.0 && high <= 65535.0)) return false;
            lo[axis] = static_cast<uint32_t>(low);
            hi[axis] = static_cast<uint32_t>(high);
        }
        return true;
    }

    // As the direct engine's skip_child without cost: a subtree whose
    // maximum is below the threshold, or unknown space when it is free.
    bool skipped(OctreeView::NodeRef node) const {
        if (settings_.unknown_occupied) return false;
        return node == nullptr || view_.log_odds(node) < settings_.threshold_log_odds;
    }
    bool skip(const OctreeCell &cell) const { return skipped(cell.node); }

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

// The descent from the root; out of line, so that the grid's answer
// costs no more than its own work.
__attribute__((noinline)) bool descend(const SensorOctree &tree, const Vec3 &center, double radius,
                                       const SphereSettings &settings) {
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

}  // namespace

bool sphere_collides(const SensorOctree &tree, const ObstacleGrid *grid, const Vec3 &center, double radius,
                     const SphereSettings &settings) {
    if (grid != nullptr && !settings.unknown_occupied && grid->threshold() == settings.threshold_log_odds) {
        const GridAnswer answer = sphere_on_grid(*grid, center, radius, settings.point_extents);
        if (answer != GridAnswer::kUndecided) return answer == GridAnswer::kYes;
    }
    return descend(tree, center, radius, settings);
}

}  // namespace octoprox
