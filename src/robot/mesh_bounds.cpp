#include "robot/mesh_bounds.hpp"

#include <cmath>
#include <limits>

namespace octoprox {
namespace {

// The largest sign * (rotation * v + center)[axis] over the mesh's
// vertices, by branch-and-bound over its triangle tree (shape frame): a
// node's box bounds the value by centre and half extent, and nodes that
// cannot beat the best vertex found (by more than the bound's rounding)
// are skipped.  Vertices are placed by the same expression as
// PlacedShape::place_mesh, so the box is bit for bit theirs.  The
// higher-bounded child goes first: about one descent finds the extreme.
double extreme(const ShapeDef &def, const Eigen::Matrix3d &rotation, const Vec3 &center, int axis, double sign) {
    const AabbTree &tree = def.mesh_tree;
    const Vec3 dir = sign * rotation.row(axis).transpose();
    const Vec3 abs_dir = dir.cwiseAbs();
    const double offset = sign * center[axis];
    const double slack = 1e-12 * (1.0 + center.cwiseAbs().maxCoeff() + tree.node(tree.root()).box.half_extent().norm());
    const auto bound = [&](int32_t index) {
        const Aabb &box = tree.node(index).box;
        return offset + dir.dot(box.center()) + abs_dir.dot(box.half_extent()) + slack;
    };
    double best = -std::numeric_limits<double>::infinity();
    int32_t stack[64];
    int top = 0;
    stack[top++] = tree.root();
    while (top > 0) {
        const int32_t index = stack[--top];
        if (bound(index) < best) continue;
        const AabbTreeNode &node = tree.node(index);
        if (node.is_leaf()) {
            for (uint32_t v : def.triangles[node.item]) {
                const Vec3 placed = rotation * def.vertices[v] + center;
                best = std::max(best, sign * placed[axis]);
            }
            continue;
        }
        const bool left_first = bound(node.left) >= bound(node.right);
        stack[top++] = left_first ? node.right : node.left;
        stack[top++] = left_first ? node.left : node.right;
    }
    return best;
}

}  // namespace

Aabb mesh_world_box(const ShapeDef &def, const Eigen::Matrix3d &rotation, const Vec3 &center) {
    Aabb box;
    if (def.mesh_tree.empty()) return box;
    for (int axis = 0; axis < 3; ++axis) {
        box.hi[axis] = extreme(def, rotation, center, axis, 1.0);
        box.lo[axis] = -extreme(def, rotation, center, axis, -1.0);
    }
    return box;
}

}  // namespace octoprox
