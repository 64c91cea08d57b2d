#include "octree/update_reserve.hpp"

#include "broadphase/morton.hpp"

#include <algorithm>
#include <vector>

namespace octoprox {
namespace {

constexpr unsigned kDepth = 16;  // OctoMap's tree depth: leaves at depth 16

// The depth of the first node on the key's path that needs a block: one
// that has no children (a leaf above the finest depth, or a pruned node),
// or the missing child of a node that has a block.  Every node below it
// on the path needs one too.  kDepth when the path exists to the leaf.
unsigned first_depth_needing_block(const BoundedOcTree &tree, const octomap::OcTreeKey &key) {
    const BoundedNode *node = tree.getRoot();
    if (node == nullptr) return 0;  // the root is made outside the pool
    for (unsigned depth = 0; depth < kDepth; ++depth) {
        if (!tree.nodeHasChildren(node)) return depth;
        const unsigned child = octomap::computeChildIdx(key, static_cast<int>(kDepth - 1 - depth));
        if (!tree.nodeChildExists(node, child)) return depth + 1;
        node = tree.getNodeChild(node, child);
    }
    return kDepth;
}

// Levels, from the root down, that two distinct Morton codes of leaf keys
// share: nodes at depths up to this one lie on both paths.
unsigned shared_depth(uint64_t a, uint64_t b) {
    const unsigned highest_differing_bit = 63u - static_cast<unsigned>(__builtin_clzll(a ^ b));
    return kDepth - 1 - highest_differing_bit / 3;
}

}  // namespace

size_t child_blocks_needed(const BoundedOcTree &tree, const FrameCells &frame) {
    // In Morton order the keys through any one node are consecutive, so a
    // node is shared with the previous key or with none before it.
    const std::vector<uint64_t> &cells = frame.cells;
    size_t blocks = 0;
    for (size_t i = 0; i < cells.size(); ++i) {
        const uint64_t code = FrameCells::code(cells[i]);
        uint32_t x, y, z;
        morton_decode(code, x, y, z);
        const octomap::OcTreeKey key(static_cast<octomap::key_type>(x), static_cast<octomap::key_type>(y),
                                     static_cast<octomap::key_type>(z));
        const unsigned needs_from = first_depth_needing_block(tree, key);
        const unsigned new_from =
            i == 0 ? needs_from : std::max(needs_from, shared_depth(FrameCells::code(cells[i - 1]), code) + 1);
        if (new_from < kDepth) blocks += kDepth - new_from;
    }
    return blocks;
}

void reserve_update(BoundedOcTree &tree, const FrameCells &cells) {
    tree.child_blocks().reserve(child_blocks_needed(tree, cells));
}

}  // namespace octoprox
