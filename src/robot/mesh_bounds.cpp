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

}  // namespace octoprox
