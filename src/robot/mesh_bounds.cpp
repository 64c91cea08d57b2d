#include "robot/mesh_bounds.hpp"

namespace octoprox {

std::vector<Aabb> mesh_frontier_boxes(const AabbTree &tree) {
    std::vector<Aabb> boxes;
    if (tree.empty()) return boxes;
    std::vector<int32_t> level{tree.root()}, next;
    for (int depth = 0; depth < kFrontierDepth; ++depth) {
        next.clear();
        for (int32_t index : level) {
            const AabbTreeNode &node = tree.node(index);
            if (node.is_leaf()) boxes.push_back(node.box);
            else next.push_back(node.left), next.push_back(node.right);
        }
        level.swap(next);
    }
    for (int32_t index : level) boxes.push_back(tree.node(index).box);
    return boxes;
}

Aabb placed_frontier_box(const std::vector<Aabb> &boxes, const Eigen::Matrix3d &rotation, const Vec3 &center) {
    const Eigen::Matrix3d spread = rotation.cwiseAbs();
    Aabb placed;
    for (const Aabb &box : boxes) {
        const Vec3 middle = rotation * box.center() + center;
        const Vec3 half = spread * box.half_extent();
        placed.grow(Aabb::from_center(middle, half));
    }
    if (placed.empty()) return placed;
    // Rounding of the rotation here and of the vertices in place_mesh.
    placed.inflate(1e-12 * (1.0 + center.cwiseAbs().maxCoeff() + (placed.hi - placed.lo).maxCoeff()));
    return placed;
}

}  // namespace octoprox
