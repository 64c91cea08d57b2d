#include "octree/compact_octree.hpp"

#include "octree/octree_view.hpp"

#include <octomap/OcTree.h>

#include <algorithm>

namespace octoprox {

const uint8_t kBitsInByte[256] = {
#define OPX_B2(n) n, n + 1, n + 1, n + 2
#define OPX_B4(n) OPX_B2(n), OPX_B2(n + 1), OPX_B2(n + 1), OPX_B2(n + 2)
#define OPX_B6(n) OPX_B4(n), OPX_B4(n + 1), OPX_B4(n + 1), OPX_B4(n + 2)
    OPX_B6(0), OPX_B6(1), OPX_B6(1), OPX_B6(2)
#undef OPX_B6
#undef OPX_B4
#undef OPX_B2
};

namespace {

// Breadth first: node i's children are appended as one block, so they
// are contiguous and always come after their parent.
void lay_out(const octomap::OcTree &tree, std::vector<CompactNode> &nodes, std::vector<CellKey> &keys) {
    std::vector<const octomap::OcTreeNode *> sources{tree.getRoot()};
    nodes.assign(1, CompactNode{});
    keys.assign(1, CellKey{});
    for (size_t i = 0; i < sources.size(); ++i) {
        const octomap::OcTreeNode *source = sources[i];
        nodes[i].log_odds = source->getLogOdds();
        if (!tree.nodeHasChildren(source)) continue;
        nodes[i].first_child = static_cast<uint32_t>(sources.size());
        for (int c = 0; c < 8; ++c) {
            if (!tree.nodeChildExists(source, c)) continue;
            nodes[i].child_mask |= static_cast<uint8_t>(1u << c);
            sources.push_back(tree.getNodeChild(source, c));
            keys.push_back(keys[i].child(c));
            nodes.emplace_back();
        }
    }
}

void grow_obstacle_bounds(CompactNode &node, const CompactNode &part) {
    if (!part.has_obstacle) return;
    for (int axis = 0; axis < 3; ++axis) {
        node.obstacle_lo[axis] = node.has_obstacle ? std::min(node.obstacle_lo[axis], part.obstacle_lo[axis])
                                                   : part.obstacle_lo[axis];
        node.obstacle_hi[axis] = node.has_obstacle ? std::max(node.obstacle_hi[axis], part.obstacle_hi[axis])
                                                   : part.obstacle_hi[axis];
    }
    node.has_obstacle = 1;
}

// Children come after parents, so one backward pass sees every child
// before its parent.
void bound_obstacles(std::vector<CompactNode> &nodes, const std::vector<CellKey> &keys, float obstacle_log_odds) {
    for (size_t i = nodes.size(); i-- > 0;) {
        CompactNode &node = nodes[i];
        if (node.child_mask == 0) {
            if (node.log_odds < obstacle_log_odds) continue;
            node.has_obstacle = 1;
            for (int axis = 0; axis < 3; ++axis) {
                node.obstacle_lo[axis] = keys[i].key[axis];
                node.obstacle_hi[axis] = static_cast<uint16_t>(keys[i].key[axis] + keys[i].width_in_cells() - 1);
            }
            continue;
        }
        const int children = kBitsInByte[node.child_mask];
        for (int c = 0; c < children; ++c) grow_obstacle_bounds(node, nodes[node.first_child + c]);
    }
}

}  // namespace

void CompactOctree::rebuild(const octomap::OcTree &tree, float obstacle_log_odds) {
    obstacle_log_odds_ = obstacle_log_odds;
    if (tree.getRoot() == nullptr) {
        nodes_.clear();
        return;
    }
    std::vector<CellKey> keys;
    lay_out(tree, nodes_, keys);
    bound_obstacles(nodes_, keys, obstacle_log_odds);
}

}  // namespace octoprox
