#include "narrowphase/narrow_phase.hpp"

#include "geometry/gjk.hpp"
#include "geometry/triangle_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {
namespace {

double point_box_distance2(const Vec3 &p, const Vec3 &center, const Vec3 &half) {
    return ((p - center).cwiseAbs() - half).cwiseMax(0.0).squaredNorm();
}

bool convex_within(const Convex &core, double limit, const Vec3 &center, const Vec3 &half) {
    if (core.kind == ConvexKind::kPoint) return point_box_distance2(core.center, center, half) <= limit * limit;
    GjkQuery query;
    query.cell_center = center;
    query.cell_half = half;
    query.shape = &core;
    query.stop_above = limit;
    query.stop_below = limit;
    const GjkResult result = gjk_cell_distance(query);
    return result.intersecting || result.distance <= limit;
}

// Whether two boxes whose centres lie `offset` apart, with half extents
// `half` and `reach` along the same three axes, lie more than the touch
// tolerance apart along one of them.
bool apart_on_axes(const Vec3 &offset, const Vec3 &half, const Vec3 &reach) {
    return ((offset.cwiseAbs() - half - reach).array() > kTouchTolerance).any();
}

// Oriented box (centre, axes, half) against an axis-aligned box, on the
// face axes of both: conservative, since the 9 edge axes are not tried.
bool oriented_box_may_touch(const Vec3 &center, const Eigen::Matrix3d &axes, const Vec3 &half,
                            const Aabb &box) {
    const Vec3 box_half = box.half_extent();
    const Vec3 offset = center - box.center();
    const Eigen::Matrix3d abs_axes = axes.cwiseAbs();
    const Vec3 reach = abs_axes * half;  // the oriented box's half extents along x, y, z
    if (apart_on_axes(offset, box_half, reach)) return false;
    const Vec3 local = axes.transpose() * offset;
    const Vec3 box_reach = abs_axes.transpose() * box_half;
    return !apart_on_axes(local, half, box_reach);
}

// Along each of the three axes (columns of `axes`, unit): how far every
// point of the box lies from `center` at the least (negative when the box
// reaches past it), from the box's half extents projected on the axis.
Vec3 box_gaps_along(const Vec3 &center, const Eigen::Matrix3d &axes, const Aabb &box) {
    const Vec3 box_half = box.half_extent();
    const Vec3 local = axes.transpose() * (center - box.center());
    Vec3 gaps;
    for (int k = 0; k < 3; ++k) {
        const Vec3 axis = axes.col(k);
        const double box_reach =
            std::abs(axis.x()) * box_half.x() + std::abs(axis.y()) * box_half.y() + std::abs(axis.z()) * box_half.z();
        gaps[k] = std::abs(local[k]) - box_reach;
    }
    return gaps;
}

// The largest gap between an oriented box and an axis-aligned box along
// the oriented box's own face axes (<= their distance; <= 0 when not
// separated there).  The map's axes are left out: every caller takes the
// maximum with the distance of the shape's axis-aligned box, which is at
// least the gap along any of them.
double oriented_box_gap(const Vec3 &center, const Eigen::Matrix3d &axes, const Vec3 &half, const Aabb &box) {
    const Vec3 gaps = box_gaps_along(center, axes, box);
    double gap = -std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) gap = std::max(gap, gaps[k] - half[k]);
    return gap;
}

// A lower bound of the distance between an axis-aligned box and the points
// within `radius` of the axis segment (half length `half_length` along
// axes.col(2)), cut flat at the segment's ends (`flat_ends`: a cylinder)
// or not (a capsule of that radius).  Every point of the box lies at least
// `across` from the axis line and `along` beyond the end planes, from the
// box's extents on the shape's axes; the two combine in quadrature, which
// the face-axis gap of the shape's oriented box does not do (that gap is
// smaller off the flat faces: at the rim and beside the round side).
double round_shape_gap(const Vec3 &center, const Eigen::Matrix3d &axes, double radius, double half_length,
                       bool flat_ends, const Aabb &box) {
    const Vec3 gaps = box_gaps_along(center, axes, box);
    double gap[3];
    for (int k = 0; k < 3; ++k) gap[k] = std::max(gaps[k], 0.0);
    const double across = std::sqrt(gap[0] * gap[0] + gap[1] * gap[1]);
    const double along = std::max(gap[2] - half_length, 0.0);
    if (!flat_ends) return std::sqrt(across * across + along * along) - radius;
    const double side = std::max(across - radius, 0.0);
    return std::sqrt(side * side + along * along);
}

// The root box of a mesh's triangle tree (its box in the mesh's frame)
// posed: an oriented box on the shape's axes, far tighter than the
// map-frame box when the mesh is turned.  False for a mesh without
// triangles (loaders and the scene parser reject those).
inline bool posed_mesh_box(const PlacedShape &shape, Vec3 &center, Vec3 &half) {
    const AabbTree &tree = shape.def->mesh_tree;
    if (tree.empty()) return false;
    const Aabb &root = tree.node(tree.root()).box;
    center = shape.core.axes * root.center() + shape.core.center;
    half = root.half_extent();
    return true;
}

// A cell grown by the limit against the posed boxes of a mesh's triangle
// tree (boxes in the mesh's own frame), on the face axes of both, as
// oriented_box_may_touch: the mesh's axes first, in the mesh's frame,
// where the cell's side of the test is the same for every node and a
// node's costs three subtractions; the map's axes for the nodes left.
class MeshNodeTest {
public:
    MeshNodeTest(const PlacedShape &shape, const Aabb &cell)
        : rotation_(shape.core.axes), abs_rotation_(rotation_.cwiseAbs()), mesh_center_(shape.core.center),
          cell_center_(cell.center()), cell_half_(cell.half_extent()),
          cell_center_in_mesh_(rotation_.transpose() * (cell_center_ - mesh_center_)),
          cell_reach_in_mesh_(abs_rotation_.transpose() * cell_half_) {}

    bool may_touch(const Aabb &node_box) const {
        const Vec3 node_center = node_box.center(), node_half = node_box.half_extent();
        if (apart_on_axes(node_center - cell_center_in_mesh_, node_half, cell_reach_in_mesh_)) return false;
        const Vec3 offset = rotation_ * node_center + mesh_center_ - cell_center_;
        return !apart_on_axes(offset, cell_half_, abs_rotation_ * node_half);
    }

private:
    const Eigen::Matrix3d &rotation_;
    const Eigen::Matrix3d abs_rotation_;
    const Vec3 mesh_center_, cell_center_, cell_half_, cell_center_in_mesh_, cell_reach_in_mesh_;
};

// A mesh's triangle against the cell: the separating axes decide all but
// the pairs within the touch tolerance of the limit or of touching, which
// GJK decides; the same answers as GJK alone.
bool triangle_within(const Convex &triangle, double limit, const Vec3 &center, const Vec3 &half) {
    switch (triangle_box_sat(triangle.v, center, half, limit, kTouchTolerance)) {
    case TriangleBoxAnswer::kApart: return false;
    case TriangleBoxAnswer::kIntersecting: return true;
    case TriangleBoxAnswer::kUndecided: break;
    }
    return convex_within(triangle, limit, center, half);
}

// Depth-first over the mesh's triangle tree in the mesh's own frame, so a
// collision query never places the mesh (most queries touch a mesh in a few
// nodes): a node's box, posed, is an oriented box, tested against the cell
// grown by the limit (MeshNodeTest); a leaf's triangle is posed (three
// vertices, as PlacedShape::place_mesh would) for the exact test.
bool mesh_within(const PlacedShape &shape, double limit, const Vec3 &center, const Vec3 &half,
                 uint64_t &narrow_tests) {
    const AabbTree &tree = shape.def->mesh_tree;
    const MeshNodeTest test(shape, Aabb::from_center(center, half + Vec3::Constant(limit)));
    int32_t stack[64];
    int top = 0;
    stack[top++] = tree.root();
    while (top > 0) {
        const AabbTreeNode &node = tree.node(stack[--top]);
        if (!test.may_touch(node.box)) continue;
        if (node.is_leaf()) {
            ++narrow_tests;
            if (triangle_within(shape.posed_triangle(node.item), limit, center, half)) return true;
            continue;
        }
        stack[top++] = node.left;
        stack[top++] = node.right;
    }
    return false;
}

}  // namespace

double shape_lower_bound(const PlacedShape &shape, const Aabb &box) {
    const Convex &core = shape.core;
    switch (shape.kind) {
    case ShapeKind::kSphere:
        return std::sqrt(point_box_distance2(core.center, box.center(), box.half_extent())) - shape.inflation;
    case ShapeKind::kBox: return oriented_box_gap(core.center, core.axes, core.half, box) - shape.inflation;
    case ShapeKind::kCylinder:
        return round_shape_gap(core.center, core.axes, core.half.x(), core.half.z(), true, box) - shape.inflation;
    case ShapeKind::kCapsule: {
        // The core is the axis segment; the radius is part of the inflation.
        const double half_length = 0.5 * (core.v[1] - core.v[0]).norm();
        return round_shape_gap(core.center, core.axes, 0.0, half_length, false, box) - shape.inflation;
    }
    case ShapeKind::kMesh: {
        Vec3 center, half;
        if (!posed_mesh_box(shape, center, half)) break;
        return oriented_box_gap(center, core.axes, half, box) - shape.inflation;
    }
    default: break;
    }
    return std::sqrt(shape.box.squared_distance(box));
}

bool shape_may_touch(const PlacedShape &shape, const Aabb &box) {
    const Convex &core = shape.core;
    const double inflation = shape.inflation;
    switch (shape.kind) {
    case ShapeKind::kSphere: {
        const double limit = inflation + kTouchTolerance;
        return point_box_distance2(core.center, box.center(), box.half_extent()) <= limit * limit;
    }
    case ShapeKind::kBox:
        return oriented_box_may_touch(core.center, core.axes, core.half + Vec3::Constant(inflation), box);
    case ShapeKind::kCylinder:
        return oriented_box_may_touch(core.center, core.axes, core.half + Vec3::Constant(inflation), box);
    case ShapeKind::kCapsule: {
        const double half_length = 0.5 * (core.v[1] - core.v[0]).norm();
        return oriented_box_may_touch(core.center, core.axes, Vec3(inflation, inflation, half_length + inflation), box);
    }
    case ShapeKind::kMesh: {
        Vec3 center, half;
        if (!posed_mesh_box(shape, center, half)) return true;
        return oriented_box_may_touch(center, core.axes, half + Vec3::Constant(inflation), box);
    }
    default: return true;
    }
}

bool shape_touches_cell(const PlacedShape &shape, const Vec3 &cell_center, const Vec3 &cell_half,
                        uint64_t &narrow_tests) {
    const double limit = shape.inflation + kTouchTolerance;
    if (shape.kind == ShapeKind::kMesh) return mesh_within(shape, limit, cell_center, cell_half, narrow_tests);
    ++narrow_tests;
    return convex_within(shape.core, limit, cell_center, cell_half);
}

}  // namespace octoprox
