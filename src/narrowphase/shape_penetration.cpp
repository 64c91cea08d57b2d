#include "narrowphase/shape_penetration.hpp"

#include "geometry/epa.hpp"
#include "geometry/gjk.hpp"
#include "narrowphase/narrow_phase.hpp"

#include <cmath>

namespace octoprox {
namespace {

// Moves the core's witness outwards by the ball: the padded surface point.
ShapePenetration padded(const Vec3 &core_point, const Vec3 &cell_point, const Vec3 &normal,
                        double core_depth, double inflation) {
    ShapePenetration p;
    p.depth = core_depth + inflation;
    p.normal = normal;
    p.on_link = core_point + inflation * normal;
    p.on_cell = cell_point;
    return p;
}

// A point inside the box leaves it fastest through the nearest face.
ShapePenetration point_inside(const Vec3 &point, const Vec3 &center, const Vec3 &half, double inflation) {
    const Vec3 offset = point - center;
    const Vec3 room = half - offset.cwiseAbs();
    int axis = 0;
    room.minCoeff(&axis);
    Vec3 normal = Vec3::Zero();
    normal[axis] = offset[axis] >= 0.0 ? -1.0 : 1.0;  // entered through that face
    Vec3 exit = point;
    exit[axis] = center[axis] - normal[axis] * half[axis];
    return padded(point, exit, normal, room[axis], inflation);
}

ShapePenetration core_penetration(const Convex &core, double inflation, const Vec3 &center, const Vec3 &half) {
    if (core.kind == ConvexKind::kPoint) {
        const Vec3 nearest = core.center.cwiseMax(center - half).cwiseMin(center + half);
        const double d = (nearest - core.center).norm();
        if (d == 0.0) return point_inside(core.center, center, half, inflation);
        return padded(core.center, nearest, (nearest - core.center) / d, -d, inflation);
    }
    GjkQuery query;
    query.cell_center = center, query.cell_half = half, query.shape = &core;
    const GjkResult r = gjk_cell_distance(query);
    if (!r.intersecting) {
        const Vec3 normal = (r.on_cell - r.on_shape) / r.distance;
        return padded(r.on_shape, r.on_cell, normal, -r.distance, inflation);
    }
    const Penetration e = epa_cell_penetration(center, half, core, r.simplex);
    return padded(e.on_shape, e.on_cell, e.normal, e.depth, inflation);
}

ShapePenetration mesh_penetration(const PlacedShape &shape, const Vec3 &center, const Vec3 &half) {
    shape.place_mesh();
    const AabbTree &tree = shape.mesh_tree;
    const double limit = shape.inflation + kTouchTolerance;
    const Aabb cell = Aabb::from_center(center, half + Vec3::Constant(limit));
    ShapePenetration deepest;
    deepest.depth = -1.0;
    int32_t stack[64];
    int top = 0;
    stack[top++] = tree.root();
    while (top > 0) {
        const AabbTreeNode &node = tree.node(stack[--top]);
        if (!node.box.overlaps(cell)) continue;
        if (!node.is_leaf()) {
            stack[top++] = node.left, stack[top++] = node.right;
            continue;
        }
        const ShapePenetration p = core_penetration(shape.triangle(node.item), shape.inflation, center, half);
        if (p.depth > deepest.depth) deepest = p;
    }
    if (deepest.depth < 0.0) deepest.depth = 0.0;
    return deepest;
}

}  // namespace

ShapePenetration shape_penetration(const PlacedShape &shape, const Vec3 &cell_center, const Vec3 &cell_half) {
    ShapePenetration p = shape.kind == ShapeKind::kMesh
                             ? mesh_penetration(shape, cell_center, cell_half)
                             : core_penetration(shape.core, shape.inflation, cell_center, cell_half);
    if (p.depth < 0.0) p.depth = 0.0;  // touching within the tolerance
    return p;
}

}  // namespace octoprox
