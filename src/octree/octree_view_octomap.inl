// OctreeView over our OctoMap occupancy octree (inline: the engines call
// these per node).
#pragma once

#include "octree/bounded_tree.hpp"

namespace octoprox {

inline OctreeView::OctreeView(const void *bounded_tree, float bounds_threshold)
    : tree_(bounded_tree),
      resolution_(static_cast<const BoundedOcTree *>(bounded_tree)->getResolution()),
      bounds_threshold_(bounds_threshold) {}

inline OctreeView::NodeRef OctreeView::root() const {
    return static_cast<const BoundedOcTree *>(tree_)->getRoot();
}

inline bool OctreeView::has_children(NodeRef node) const {
    return static_cast<const BoundedNode *>(node)->has_child_array();
}

inline OctreeView::NodeRef OctreeView::child(NodeRef node, int index) const {
    const auto *tree = static_cast<const BoundedOcTree *>(tree_);
    const auto *n = static_cast<const BoundedNode *>(node);
    return tree->nodeChildExists(n, index) ? tree->getNodeChild(n, index) : nullptr;
}

inline void OctreeView::prefetch_children(NodeRef node, unsigned mask) const {
    for (unsigned bits = mask; bits != 0; bits &= bits - 1)
        if (NodeRef next = child(node, __builtin_ctz(bits))) __builtin_prefetch(next);
}

inline void OctreeView::prefetch_child_array(NodeRef node) const {
    __builtin_prefetch(static_cast<const BoundedNode *>(node)->child_array());
}

inline float OctreeView::log_odds(NodeRef node) const {
    return static_cast<const BoundedNode *>(node)->getLogOdds();
}

inline uint32_t OctreeView::packed_obstacle_bounds(NodeRef node) const {
    return static_cast<const BoundedNode *>(node)->packed_bounds();
}

}  // namespace octoprox
