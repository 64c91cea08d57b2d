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

inline OctreeView::NodeRef OctreeView::child_or_absent(NodeRef node, int index) const {
    const auto *block = static_cast<const char *>(static_cast<const BoundedNode *>(node)->child_array());
    return block + child_block::kSlotsOffset + child_block::kSlotBytes * static_cast<size_t>(index);
}

// The block's line of child pointers (child() reads them) and its lines
// holding the children in `mask` (slots 0-3 share one line, 4-7 the
// next), without reading any of them.
inline void OctreeView::prefetch_children(NodeRef node, unsigned mask) const {
    const auto *block = static_cast<const char *>(static_cast<const BoundedNode *>(node)->child_array());
    if (block == nullptr) return;
    __builtin_prefetch(block);
    if (mask & 0x0Fu) __builtin_prefetch(block + child_block::kSlotsOffset);
    if (mask & 0xF0u) __builtin_prefetch(block + child_block::kSlotsOffset + 64);
}

inline float OctreeView::log_odds(NodeRef node) const {
    return static_cast<const BoundedNode *>(node)->getLogOdds();
}

inline uint32_t OctreeView::packed_obstacle_bounds(NodeRef node) const {
    return static_cast<const BoundedNode *>(node)->packed_bounds();
}

inline uint32_t OctreeView::point_extent(NodeRef node) const {
    return static_cast<const BoundedNode *>(node)->point_extent();
}

}  // namespace octoprox
