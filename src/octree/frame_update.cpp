#include "octree/frame_update.hpp"

#include "octree/bounded_tree.hpp"

namespace octoprox {
namespace {

constexpr int kDepth = 16;  // OctoMap's leaves

class FrameUpdate {
public:
    explicit FrameUpdate(BoundedOcTree &tree)
        : tree_(tree),
          hit_(tree.getProbHitLog()),
          miss_(tree.getProbMissLog()),
          clamp_min_(tree.getClampingThresMinLog()),
          clamp_max_(tree.getClampingThresMaxLog()) {}

    void run(const uint64_t *first, const uint64_t *last) {
        if (first == last) return;
        bool created = false;
        BoundedNode *root = tree_.root_for_update(created);
        apply(root, 0, created, first, last);
    }

private:
    // OctoMap's early exit: the leaf holding the cell is clamped in the
    // direction of the cell's update.
    bool clamped_for(const BoundedNode *leaf, uint64_t cell) const {
        const float value = leaf->getLogOdds();
        return FrameCells::is_hit(cell) ? value >= clamp_max_ : value <= clamp_min_;
    }
    bool all_clamped_for(const BoundedNode *leaf, const uint64_t *first, const uint64_t *last) const {
        for (const uint64_t *cell = first; cell != last; ++cell)
            if (!clamped_for(leaf, *cell)) return false;
        return true;
    }

    static unsigned child_index(uint64_t cell, int depth) {
        return static_cast<unsigned>((FrameCells::code(cell) >> (3 * (kDepth - 1 - depth))) & 7);
    }

    // Updates the cells [first, last), all inside `node` (at `depth`);
    // returns whether anything below the node changed.
    bool apply(BoundedNode *node, int depth, bool created, const uint64_t *first, const uint64_t *last) {
        if (depth == kDepth) {
            if (!created && clamped_for(node, *first)) return false;
            tree_.updateNodeLogOdds(node, FrameCells::is_hit(*first) ? hit_ : miss_);
            return true;
        }
        if (!created && !tree_.nodeHasChildren(node)) {
            // A leaf above the finest depth (pruned): every cell inside it
            // holds its value, so it opens only for a cell it does not
            // already clamp.
            if (all_clamped_for(node, first, last)) return false;
            tree_.expandNode(node);
        }
        bool changed = false;
        while (first != last) {
            const unsigned index = child_index(*first, depth);
            const uint64_t *group_end = first + 1;
            while (group_end != last && child_index(*group_end, depth) == index) ++group_end;
            const bool exists = tree_.nodeChildExists(node, index);
            BoundedNode *child = exists ? tree_.getNodeChild(node, index) : tree_.createNodeChild(node, index);
            changed |= apply(child, depth + 1, !exists, first, group_end);
            first = group_end;
        }
        if (changed && !tree_.pruneNode(node)) node->updateOccupancyChildren();
        return changed;
    }

    BoundedOcTree &tree_;
    const float hit_, miss_, clamp_min_, clamp_max_;
};

}  // namespace

void apply_frame_cells(BoundedOcTree &tree, const FrameCells &cells) {
    FrameUpdate(tree).run(cells.cells.data(), cells.cells.data() + cells.cells.size());
}

}  // namespace octoprox
