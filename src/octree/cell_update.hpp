// One thread's part of a frame update (frame_update.hpp): the frame's
// cells below one node, in Morton order, applied depth first as OctoMap's
// updateNode applies them one by one.
#pragma once

#include "octree/bounded_tree.hpp"
#include "octree/frame_cells.hpp"
#include "octree/point_extent.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace octoprox {

class CellUpdate {
public:
    static constexpr int kDepth = 16;  // OctoMap's leaves

    CellUpdate(BoundedOcTree &tree, const std::vector<CellExtent> &extents, float occupied_log_odds)
        : tree_(tree),
          hit_(tree.getProbHitLog()),
          miss_(tree.getProbMissLog()),
          clamp_min_(tree.getClampingThresMinLog()),
          clamp_max_(tree.getClampingThresMaxLog()),
          occupied_(occupied_log_odds),
          extents_(extents) {}

    static unsigned child_index(uint64_t cell, int depth) {
        return static_cast<unsigned>((FrameCells::code(cell) >> (3 * (kDepth - 1 - depth))) & 7);
    }

    // The end of the run of cells from `first` under the same child of a
    // node at `depth`.  A run near the root holds most of the frame, so it
    // is found by galloping, not by reading every cell at every level.
    static const uint64_t *group_end(const uint64_t *first, const uint64_t *last, int depth) {
        const unsigned index = child_index(*first, depth);
        const auto same = [&](const uint64_t *cell) { return child_index(*cell, depth) == index; };
        size_t step = 1;
        const uint64_t *inside = first;  // same child
        while (static_cast<size_t>(last - inside) > step && same(inside + step)) {
            inside += step;
            step *= 2;
        }
        const uint64_t *outside = static_cast<size_t>(last - inside) > step ? inside + step : last;
        while (outside - inside > 1) {  // inside same, outside not (or last)
            const uint64_t *middle = inside + (outside - inside) / 2;
            (same(middle) ? inside : outside) = middle;
        }
        return outside;
    }

    // Whether the cells [first, last) inside `node` (at `depth`, above the
    // leaves) go on to its children.  A leaf above the finest depth
    // (pruned) holds the value of every cell inside it, so it opens only
    // for a cell it does not already clamp (else its points still join its
    // extent, and nothing changes).
    bool opened(BoundedNode *node, int depth, bool created, const uint64_t *first, const uint64_t *last) {
        if (created || tree_.nodeHasChildren(node)) return true;
        if (all_clamped_for(node, first, last)) {
            for (const uint64_t *cell = first; cell != last; ++cell)
                if (FrameCells::is_hit(*cell)) add_points(node, depth, *cell, node->getLogOdds());
            return false;
        }
        tree_.expandNode(node);
        return true;
    }

    // The way up from a node whose children changed: pruned, or its
    // occupancy (and obstacle box) recomputed.
    void changed_below(BoundedNode *node) {
        if (!tree_.pruneNode(node)) node->updateOccupancyChildren();
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
        // A new node whose every cell misses ends as one leaf of the value
        // of one miss: OctoMap makes each cell such a leaf, then prunes
        // them into the node level by level.  A free leaf above the finest
        // depth whose every cell misses ends the same way, one miss lower.
        // Most of a large frame's free space goes in so, without a node
        // below the one kept.
        if ((created || misses_keep_one_leaf(node)) && all_cells_missed(depth, first, last)) {
            update_leaf(node, created, *first);
            return true;
        }
        if (!opened(node, depth, created, first, last)) return false;
        bool changed = false;
        while (first != last) {
            const unsigned index = child_index(*first, depth);
            const uint64_t *end = group_end(first, last, depth);
            const bool exists = tree_.nodeChildExists(node, index);
            BoundedNode *child = exists ? tree_.getNodeChild(node, index) : tree_.createNodeChild(node, index);
            changed |= apply(child, depth + 1, !exists, first, end);
            first = end;
        }
        if (changed) changed_below(node);
        return changed;
    }

private:
    // Whether the cells [first, last), all inside one node at `depth` and
    // each there once, are every cell of that node, and all misses.
    static bool all_cells_missed(int depth, const uint64_t *first, const uint64_t *last) {
        if (static_cast<uint64_t>(last - first) != uint64_t{1} << (3 * (kDepth - depth))) return false;
        for (; first != last; ++first)
            if (FrameCells::is_hit(*first) || FrameCells::is_clear(*first)) return false;
        return true;
    }

    // A leaf above the finest depth (pruned) that one more miss in every
    // cell changes alike, each cell as the leaf: free or uncertain (no
    // point extent to keep) and not clamped (else OctoMap leaves it alone).
    bool misses_keep_one_leaf(const BoundedNode *node) const {
        if (tree_.nodeHasChildren(node)) return false;
        const float value = node->getLogOdds();
        return value < occupied_ && value > clamp_min_;
    }

    // OctoMap's early exit: the leaf holding the cell is clamped in the
    // direction of the cell's update (a cleared cell's is a miss's).
    bool clamped_for(const BoundedNode *leaf, uint64_t cell) const {
        const float value = leaf->getLogOdds();
        return FrameCells::is_hit(cell) ? value >= clamp_max_ : value <= clamp_min_;
    }
    bool all_clamped_for(const BoundedNode *leaf, const uint64_t *first, const uint64_t *last) const {
        for (const uint64_t *cell = first; cell != last; ++cell)
            if (!clamped_for(leaf, *cell)) return false;
        return true;
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
        if (FrameCells::is_clear(cell)) {
            leaf->setLogOdds(clamp_min_);
            leaf->set_point_extent(0);
            return;
        }
        tree_.updateNodeLogOdds(leaf, hit ? hit_ : miss_);
        if (hit) add_points(leaf, kDepth, cell, before);
        else if (!(leaf->getLogOdds() >= occupied_)) leaf->set_point_extent(0);
    }

    BoundedOcTree &tree_;
    const float hit_, miss_, clamp_min_, clamp_max_, occupied_;
    const std::vector<CellExtent> &extents_;
    size_t next_extent_ = 0;
};


}  // namespace octoprox
