#include "octree/update_reserve.hpp"

#include "base/parallel.hpp"
#include "octree/update_worker.hpp"

#include <algorithm>
#include <vector>

namespace octoprox {
namespace {

constexpr unsigned kDepth = 16;  // OctoMap's tree depth: leaves at depth 16
// Below this many cells per thread an update counts its blocks on fewer threads.
constexpr size_t kCellsPerThread = size_t{1} << 16;

// Levels, from the root down, that two distinct Morton codes of leaf keys
// share: nodes at depths up to this one lie on both paths.
unsigned shared_depth(uint64_t a, uint64_t b) {
    const unsigned highest_differing_bit = 63u - static_cast<unsigned>(__builtin_clzll(a ^ b));
    return kDepth - 1 - highest_differing_bit / 3;
}

// The nodes on the path of the last cell looked at, from the root down,
// and how deep that path exists: the next cell, sharing the first levels
// in Morton order, walks on from where the paths part.
class PathWalk {
public:
    explicit PathWalk(const BoundedOcTree &tree) : tree_(tree) { nodes_[0] = tree.getRoot(); }

    // The depth of the first node on the cell's path that needs a block:
    // one that has no children (a leaf above the finest depth, or a pruned
    // node), or the missing child of a node that has a block.  Every node
    // below it on the path needs one too.  kDepth when the path exists to
    // the leaf.  `shared`: the depths the cell shares with the previous
    // one (-1 for the first cell).
    unsigned first_depth_needing_block(uint64_t code, int shared) {
        if (nodes_[0] == nullptr) return 0;  // the root is made outside the pool
        // The previous path ended within the shared part: so does this one.
        if (static_cast<int>(ended_at_) <= shared) return ended_at_;
        for (unsigned depth = static_cast<unsigned>(std::max(shared, 0)); depth < kDepth; ++depth) {
            const BoundedNode *node = nodes_[depth];
            if (!tree_.nodeHasChildren(node)) return ended_at_ = depth;
            const unsigned child = static_cast<unsigned>(code >> (3 * (kDepth - 1 - depth))) & 7;
            if (!tree_.nodeChildExists(node, child)) return ended_at_ = depth + 1;
            nodes_[depth + 1] = tree_.getNodeChild(node, child);
        }
        return ended_at_ = kDepth;
    }

private:
    const BoundedOcTree &tree_;
    const BoundedNode *nodes_[kDepth + 1] = {};
    unsigned ended_at_ = kDepth + 1;  // no path walked yet
};

// The blocks cells [begin, end) add to those of the cells before them.
// The first cell's path is walked from the root, but only its nodes below
// those it shares with the cell before it count.
size_t blocks_needed_by(const BoundedOcTree &tree, const uint64_t *cells, size_t begin, size_t end) {
    PathWalk walk(tree);
    size_t blocks = 0;
    for (size_t i = begin; i < end; ++i) {
        const uint64_t code = FrameCells::code(cells[i]);
        const int shared = i == 0 ? -1 : static_cast<int>(shared_depth(FrameCells::code(cells[i - 1]), code));
        const unsigned needs_from = walk.first_depth_needing_block(code, i == begin ? -1 : shared);
        const unsigned new_from = std::max(needs_from, static_cast<unsigned>(shared + 1));
        if (new_from < kDepth) blocks += kDepth - new_from;
    }
    return blocks;
}

}  // namespace

size_t child_blocks_needed(const BoundedOcTree &tree, const FrameCells &frame, size_t threads) {
    // In Morton order the keys through any one node are consecutive, so a
    // node is shared with the previous key or with none before it.
    const size_t count = frame.cells.size();
    threads = std::max<size_t>(1, std::min(threads, count));
    std::vector<size_t> blocks(threads, 0);
    run_tasks(threads, [&](size_t t) {
        blocks[t] = blocks_needed_by(tree, frame.cells.data(), count * t / threads, count * (t + 1) / threads);
    });
    size_t total = 0;
    for (const size_t b : blocks) total += b;
    return total;
}

void reserve_update(BoundedOcTree &tree, const FrameCells &cells, size_t threads) {
    const size_t batches = threads > 1 ? threads * UpdateWorker::kBatch : 0;
    const size_t counting_threads = std::min(threads, cells.cells.size() / kCellsPerThread + 1);
    tree.child_blocks().reserve(child_blocks_needed(tree, cells, counting_threads) + batches);
}

}  // namespace octoprox
