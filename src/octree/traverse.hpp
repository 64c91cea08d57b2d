// Depth-first traversal of the leaves of an octree view.
#pragma once

#include "octree/octree_view.hpp"

namespace octoprox {

// Calls visit_leaf(node, cell) for every leaf (observed cell) and
// visit_inner(node, cell) for every node with children, depth first, in
// child order.  Recursion depth is bounded by kTreeDepth.
template <class LeafVisitor, class InnerVisitor>
void traverse_nodes(const OctreeView &view, OctreeView::NodeRef node, const CellKey &cell,
                    LeafVisitor &&visit_leaf, InnerVisitor &&visit_inner) {
    if (!view.has_children(node)) {
        visit_leaf(node, cell);
        return;
    }
    visit_inner(node, cell);
    for (int i = 0; i < 8; ++i) {
        if (OctreeView::NodeRef child = view.child(node, i))
            traverse_nodes(view, child, cell.child(i), visit_leaf, visit_inner);
    }
}

template <class LeafVisitor>
void for_each_leaf(const OctreeView &view, LeafVisitor &&visit_leaf) {
    if (OctreeView::NodeRef root = view.root())
        traverse_nodes(view, root, CellKey{}, visit_leaf, [](OctreeView::NodeRef, const CellKey &) {});
}

}  // namespace octoprox
