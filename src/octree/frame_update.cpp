#include "octree/frame_update.hpp"

#include "octree/bounded_tree.hpp"

#include <limits>

namespace octoprox {
namespace {

constexpr int kDepth = 16;  // OctoMap's leaves

class FrameUpdate {
public:
    FrameUpdate(BoundedOcTree &tree, const std::vector<CellExtent> &extents, float occupied_log_odds)
        : tree_(tree),
          hit_(tree.getProbHitLog()),
          miss_(tree.getProbMissLog()),
          clamp_min_(tree.getClampingThresMinLog()),
          clamp_max_(tree.getClampingThresMaxLog()),
          occupied_(occupied_log_odds),
          extents_(extents) {}

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

    // The frame's extent of hit cell `code`: the cells come in ascending
    // order, so a cursor finds each.
    uint32_t frame_extent(uint64_t code) {
        while (next_extent_ < extents_.size() && extents_[next_extent_].code < code) ++next_extent_;
        if (next_extent_ < extents_.size() && extents_[next_extent_].code == code) return extents_[next_extent_].packed;
        return 0;
    }

    // A leaf (at `depth`) takes the frame's points of hit cell `cell`; its
    // log-odds before the frame's update was `before`.
    void add_points(BoundedNode *leaf, int depth, uint64_t cell, float before) {
        const uint32_t frame = frame_extent(FrameCells::code(cell));
        if (frame == 0) return;
        const uint32_t lifted = extent::lift(frame, FrameCells::code(cell), kDepth - depth);
        const uint32_t kept = leaf->point_extent();
        if (extent::valid(kept)) leaf->set_point_extent(extent::merge(kept, lifted));
        else if (!(before >= occupied_)) leaf->set_point_extent(lifted);
    }

    void update_leaf(BoundedNode *leaf, bool created, uint64_t cell) {
        const float before = created ? -std::numeric_limits<float>::infinity() : leaf->getLogOdds();
        const bool hit = FrameCells::is_hit(cell);
        tree_.updateNodeLogOdds(leaf, hit ? hit_ : miss_);
        if (hit) add_points(leaf, kDepth, cell, before);
        else if (!(leaf->getLogOdds() >= occupied_)) leaf->set_point_extent(0);
    }

    // Updates the cells [first, last), all inside `node` (at `depth`);
    // returns whether anything below the node changed.
    bool apply(BoundedNode *node, int depth, bool created, const uint64_t *first, const uint64_t *last) {
        if (depth == kDepth) {
            if (!created && clamped_for(node, *first)) {
                if (FrameCells::is_hit(*first)) add_points(node, depth, *first, node->getLogOdds());
                return false;
            }
            update_leaf(node, created, *first);
            return true;
        }
        if (!created && !tree_.nodeHasChildren(node)) {
            // A leaf above the finest depth (pruned): every cell inside it
            // holds its value, so it opens only for a cell it does not
            // already clamp (its points still join its extent).
            if (all_clamped_for(node, first, last)) {
                for (const uint64_t *cell = first; cell != last; ++cell)
                    if (FrameCells::is_hit(*cell)) add_points(node, depth, *cell, node->getLogOdds());
                return false;
            }
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
    const float hit_, miss_, clamp_min_, clamp_max_, occupied_;
    const std::vector<CellExtent> &extents_;
    size_t next_extent_ = 0;
};

}  // namespace

void apply_frame_cells(BoundedOcTree &tree, const FrameCells &cells, const std::vector<CellExtent> &extents,
                       float occupied_log_odds) {
    FrameUpdate(tree, extents, occupied_log_odds)
        .run(cells.cells.data(), cells.cells.data() + cells.cells.size());
}

}  // namespace octoprox
