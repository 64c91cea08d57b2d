// OctreeView over octomap::OcTree (inline: the engines call these per node).
#pragma once

#include <octomap/OcTree.h>

namespace octoprox {

inline OctreeView::OctreeView(const void *octomap_tree)
    : tree_(octomap_tree),
      resolution_(static_cast<const octomap::OcTree *>(octomap_tree)->getResolution()) {}

inline OctreeView::NodeRef OctreeView::root() const {
    return static_cast<const octomap::OcTree *>(tree_)->getRoot();
}

inline bool OctreeView::has_children(NodeRef node) const {
    return static_cast<const octomap::OcTree *>(tree_)->nodeHasChildren(
        static_cast<const octomap::OcTreeNode *>(node));
}

inline OctreeView::NodeRef OctreeView::child(NodeRef node, int index) const {
    const auto *tree = static_cast<const octomap::OcTree *>(tree_);
    const auto *n = static_cast<const octomap::OcTreeNode *>(node);
    return tree->nodeChildExists(n, index) ? tree->getNodeChild(n, index) : nullptr;
}

inline float OctreeView::log_odds(NodeRef node) const {
    return static_cast<const octomap::OcTreeNode *>(node)->getLogOdds();
}

}  // namespace octoprox
