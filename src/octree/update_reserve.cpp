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

void append_codes(const octomap::KeySet &keys, std::vector<uint64_t> &codes) {
    for (const octomap::OcTreeKey &key : keys) codes.push_back(morton_encode(key[0], key[1], key[2]));
}

}  // namespace

size_t child_blocks_needed(const BoundedOcTree &tree, const octomap::KeySet &first, const octomap::KeySet &second) {
    std::vector<uint64_t> codes;
    codes.reserve(first.size() + second.size());
    append_codes(first, codes);
    append_codes(second, codes);
    // In Morton order the keys through any one node are consecutive, so a
    // node is shared with the previous key or with none before it.
    std::sort(codes.begin(), codes.end());
    codes.erase(std::unique(codes.begin(), codes.end()), codes.end());
    size_t blocks = 0;
    for (size_t i = 0; i < codes.size(); ++i) {
        uint32_t x, y, z;
        morton_decode(codes[i], x, y, z);
        const octomap::OcTreeKey key(static_cast<octomap::key_type>(x), static_cast<octomap::key_type>(y),
                                     static_cast<octomap::key_type>(z));
        const unsigned needs_from = first_depth_needing_block(tree, key);
        const unsigned new_from = i == 0 ? needs_from : std::max(needs_from, shared_depth(codes[i - 1], codes[i]) + 1);
        if (new_from < kDepth) blocks += kDepth - new_from;
    }
    return blocks;
}

void reserve_update(BoundedOcTree &tree, const octomap::KeySet &first, const octomap::KeySet &second) {
    tree.child_blocks().reserve(child_blocks_needed(tree, first, second));
}

}  // namespace octoprox
