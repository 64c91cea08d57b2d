#include "narrowphase/shape_distance.hpp"

#include "geometry/cylinder_distance.hpp"
#include "geometry/gjk.hpp"

#include <algorithm>

namespace octoprox {
namespace {

// Core distance by GJK, then the ball: the witness moves from the core
// towards the cell by the inflation.
bool convex_distance(const Convex &core, double inflation, const Vec3 &center, const Vec3 &half,
                     double bound, ShapeCellDistance &out) {
    GjkQuery query;
    query.cell_center = center;
    query.cell_half = half;
    query.shape = &core;
    query.stop_above = bound + inflation;
    if (core.kind == ConvexKind::kPoint) {
        const Vec3 on_cell = core.center.cwiseMax(center - half).cwiseMin(center + half);
        const double d = (core.center - on_cell).norm();
        if (d - inflation >= bound) return false;
        out.on_cell = on_cell;
        out.on_shape = d > 0.0 ? Vec3(core.center + (on_cell - core.center) * std::min(1.0, inflation / d))
                               : on_cell;
        out.distance = std::max(0.0, d - inflation);
        return true;
    }
    const GjkResult r = core.kind == ConvexKind::kCylinder ? cylinder_cell_distance(query) : gjk_cell_distance(query);
    if (!r.intersecting && r.distance - inflation >= bound) return false;
    const double d = r.intersecting ? 0.0 : r.distance;
    out.on_cell = r.intersecting ? center : r.on_cell;
    out.on_shape = r.intersecting ? center : r.on_shape;
    if (d > 0.0) out.on_shape += (r.on_cell - r.on_shape) * std::min(1.0, inflation / d);
    out.distance = std::max(0.0, d - inflation);
    return true;
}

// Nearest-first over the mesh's triangle tree.  Nodes carry the squared
// distance of their box to the cell, computed once when pushed; a node is
// skipped when that distance minus the inflation reaches the bound.
bool mesh_distance(const PlacedShape &shape, const Vec3 &center, const Vec3 &half, double bound,
                   ShapeCellDistance &out, uint64_t &narrow_tests) {
    shape.place_mesh();
    const AabbTree &tree = shape.mesh_tree;
    const Aabb cell = Aabb::from_center(center, half);
    // Squares only where they cannot underflow (signed queries search with
    // a bound of 1e-300).
    auto beyond = [&](double squared) {
        const double reach = bound + shape.inflation;
        if (reach <= 0.0) return true;
        return reach > 1e-100 ? squared >= reach * reach : std::sqrt(squared) >= reach;
    };
    bool found = false;
    struct Entry {
        int32_t node;
        double squared;
    } stack[64];
    int top = 0;
    stack[top++] = {tree.root(), tree.node(tree.root()).box.squared_distance(cell)};
    while (top > 0) {
        const Entry entry = stack[--top];
        if (beyond(entry.squared)) continue;
        const AabbTreeNode &node = tree.node(entry.node);
        if (node.is_leaf()) {
            ++narrow_tests;
            ShapeCellDistance candidate;
            if (convex_distance(shape.triangle(node.item), shape.inflation, center, half, bound, candidate)) {
                out = candidate, bound = candidate.distance, found = true;
                if (bound <= 0.0) return true;
            }
            continue;
        }
        // Push the farther child first so the nearer one is popped first.
        const Entry left{node.left, tree.node(node.left).box.squared_distance(cell)};
        const Entry right{node.right, tree.node(node.right).box.squared_distance(cell)};
        const bool left_nearer = left.squared <= right.squared;
        stack[top++] = left_nearer ? right : left;
        stack[top++] = left_nearer ? left : right;
    }
    return found;
}

}  // namespace

bool shape_cell_distance(const PlacedShape &shape, const Vec3 &cell_center, const Vec3 &cell_half,
                         double bound, ShapeCellDistance &out, uint64_t &narrow_tests) {
    if (shape.kind == ShapeKind::kMesh) return mesh_distance(shape, cell_center, cell_half, bound, out, narrow_tests);
    ++narrow_tests;
    return convex_distance(shape.core, shape.inflation, cell_center, cell_half, bound, out);
}

}  // namespace octoprox
