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

double rotated_box_looseness(const Aabb &local, const std::vector<Vec3> &vertices) {
    constexpr int kRotations = 24;
    if (vertices.empty() || local.empty()) return 1.0;
    // A fixed pseudo-random sequence: the measure is the same on every run.
    uint64_t state = 0x9E3779B97F4A7C15ull;
    auto next = [&state] {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return static_cast<double>(state >> 11) / static_cast<double>(uint64_t{1} << 52) - 1.0;  // [-1, 1)
    };
    double sum = 0.0;
    for (int k = 0; k < kRotations; ++k) {
        Eigen::Quaterniond q(next(), next(), next(), next());
        if (q.squaredNorm() < 1e-6) q = Eigen::Quaterniond::Identity();
        const Eigen::Matrix3d rotation = q.normalized().toRotationMatrix();
        Aabb exact;
        for (const Vec3 &v : vertices) exact.grow(rotation * v);
        const Vec3 placed = rotation.cwiseAbs() * local.half_extent();
        const double exact_edges = (exact.hi - exact.lo).sum();
        sum += exact_edges > 0.0 ? 2.0 * placed.sum() / exact_edges : 1.0;
    }
    return sum / kRotations;
}

}  // namespace octoprox
