// A binary AABB tree over items (triangles of a mesh, shapes of a robot).
// The topology is built once, top-down by median split; poses then only
// refit the boxes bottom-up, which is O(n) and keeps the tree valid.
#pragma once

#include "geometry/aabb.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

struct AabbTreeNode {
    Aabb box;
    int32_t left = -1;   // children; -1 for a leaf
    int32_t right = -1;
    int32_t item = -1;   // the item of a leaf
    bool is_leaf() const { return left < 0; }
};

class AabbTree {
public:
    // Builds the topology from the items' current boxes (one box per item).
    void build(const std::vector<Aabb> &item_boxes);
    // Recomputes every box from the items' new boxes (same items, same order).
    void refit(const std::vector<Aabb> &item_boxes);

    bool empty() const { return nodes_.empty(); }
    int32_t root() const { return 0; }
    const AabbTreeNode &node(int32_t index) const { return nodes_[index]; }
    const AabbTreeNode *nodes() const { return nodes_.data(); }  // in the order below
    size_t size() const { return nodes_.size(); }
    // The leaves' indices, in tree order (left to right).
    const std::vector<int32_t> &leaves() const { return leaves_; }

private:
    int32_t build_range(std::vector<int32_t> &items, size_t begin, size_t end,
                        const std::vector<Aabb> &item_boxes);

    // Depth-first pre-order, left subtree before right: parents precede
    // their children (a reverse sweep refits bottom-up), and a node's left
    // child is the next node, which keeps a walk from the root to a leaf
    // on few cache lines.
    std::vector<AabbTreeNode> nodes_;
    // For searches that take the leaves one by one (the distance query):
    // they read no inner node.
    std::vector<int32_t> leaves_;
};

}  // namespace octoprox
