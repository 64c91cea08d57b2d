#include "octree/frame_update.hpp"

#include "base/parallel.hpp"
#include "octree/bounded_tree.hpp"
#include "octree/cell_update.hpp"
#include "octree/update_worker.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <mutex>

namespace octoprox {
namespace {

// Below this many cells a frame updates on the caller's thread: starting
// a thread costs more than it saves.
constexpr size_t kCellsPerThread = size_t{1} << 15;

// The frame's cells split by the subtrees at `split_depth`: the levels
// above are walked first on the caller's thread (creating and expanding
// nodes as the single pass does), the subtrees are then updated on the
// workers, and the levels above are finished bottom up on the caller's
// thread.  Subtrees are disjoint, so the map is the single pass's.
class SplitUpdate {
public:
    SplitUpdate(BoundedOcTree &tree, const std::vector<CellExtent> &extents, float occupied_log_odds,
                int split_depth)
        : tree_(tree), extents_(extents), occupied_(occupied_log_odds), split_depth_(split_depth),
          upper_(tree, extents, occupied_log_odds) {}

    void run(const uint64_t *first, const uint64_t *last, size_t threads) {
        bool created = false;
        BoundedNode *root = tree_.root_for_update(created);
        plan(root, 0, created, first, last);
        update_subtrees(task_count(threads, subtrees_.size()));
        finish_upper_levels();
    }

private:
    struct Subtree {
        BoundedNode *node;
        bool created;
        const uint64_t *first, *last;
        bool changed;
    };
    // A node above the split whose children were opened: its children's
    // references are refs_[first_ref, last_ref).
    struct UpperNode {
        BoundedNode *node;
        size_t first_ref, last_ref;
    };
    // A child's reference: a subtree's index, ~index of an upper node, or
    // kUnchanged.
    static constexpr long kUnchanged = std::numeric_limits<long>::min();

    long plan(BoundedNode *node, int depth, bool created, const uint64_t *first, const uint64_t *last) {
        if (depth == split_depth_) {
            subtrees_.push_back(Subtree{node, created, first, last, false});
            return static_cast<long>(subtrees_.size() - 1);
        }
        if (!upper_.opened(node, depth, created, first, last)) return kUnchanged;
        long children[8];
        int count = 0;
        while (first != last) {
            const unsigned index = CellUpdate::child_index(*first, depth);
            const uint64_t *end = CellUpdate::group_end(first, last, depth);
            const bool exists = tree_.nodeChildExists(node, index);
            BoundedNode *child = exists ? tree_.getNodeChild(node, index) : tree_.createNodeChild(node, index);
            children[count++] = plan(child, depth + 1, !exists, first, end);
            first = end;
        }
        const size_t first_ref = refs_.size();
        refs_.insert(refs_.end(), children, children + count);
        upper_nodes_.push_back(UpperNode{node, first_ref, refs_.size()});
        return ~static_cast<long>(upper_nodes_.size() - 1);
    }

    // Workers take subtrees in ascending order, each through its own
    // cursor over the frame's extents.
    void update_subtrees(size_t threads) {
        std::mutex pool_lock;
        std::atomic<size_t> next{0};
        std::vector<long> nodes_added(threads, 0);
        std::vector<char> size_changed(threads, 0);
        run_tasks(threads, [&](size_t t) {
            const BoundsScope scope(occupied_);
            UpdateWorker worker(tree_.child_blocks(), pool_lock);
            const UpdateWorker::Scope installed(worker);
            CellUpdate update(tree_, extents_, occupied_);
            for (size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < subtrees_.size();) {
                Subtree &s = subtrees_[i];
                s.changed = update.apply(s.node, split_depth_, s.created, s.first, s.last);
            }
            nodes_added[t] = worker.nodes_added();
            size_changed[t] = worker.size_changed();
        });
        for (size_t t = 0; t < threads; ++t)
            if (size_changed[t]) tree_.add_worker_nodes(nodes_added[t]);
    }

    // Upper nodes were recorded after their children: in that order every
    // child is finished before its parent.
    void finish_upper_levels() {
        std::vector<bool> changed(upper_nodes_.size(), false);
        for (size_t i = 0; i < upper_nodes_.size(); ++i) {
            const UpperNode &upper = upper_nodes_[i];
            bool any = false;
            for (size_t r = upper.first_ref; r < upper.last_ref; ++r) {
                const long ref = refs_[r];
                if (ref == kUnchanged) continue;
                any |= ref >= 0 ? subtrees_[static_cast<size_t>(ref)].changed : changed[static_cast<size_t>(~ref)];
            }
            changed[i] = any;
            if (any) upper_.changed_below(upper.node);
        }
    }

    BoundedOcTree &tree_;
    const std::vector<CellExtent> &extents_;
    const float occupied_;
    const int split_depth_;
    CellUpdate upper_;  // the levels above the split
    std::vector<Subtree> subtrees_;
    std::vector<UpperNode> upper_nodes_;
    std::vector<long> refs_;
};

// The depth whose subtrees are about a quarter of the frame's box across,
// so that even a frame on one side of the map splits into tens of them.
int split_depth_for(const KeyBox &box) {
    uint32_t widest = 1;
    for (int axis = 0; axis < 3; ++axis) widest = std::max(widest, box.hi[axis] - box.lo[axis] + 1);
    int level = 0;  // subtrees 2^level cells across
    while (level < 13 && (uint32_t{4} << level) < widest) ++level;
    return CellUpdate::kDepth - std::max(level, 3);
}

}  // namespace

size_t frame_update_threads(const FrameCells &cells, uint32_t max_threads) {
    return task_count(max_threads, cells.cells.size() / kCellsPerThread + 1);
}

void apply_frame_cells_split(BoundedOcTree &tree, const FrameCells &cells, const std::vector<CellExtent> &extents,
                             float occupied_log_odds, size_t threads, int split_depth) {
    if (cells.cells.empty()) return;
    const uint64_t *first = cells.cells.data(), *last = first + cells.cells.size();
    SplitUpdate(tree, extents, occupied_log_odds, split_depth).run(first, last, threads);
}

void apply_frame_cells(BoundedOcTree &tree, const FrameCells &cells, const std::vector<CellExtent> &extents,
                       float occupied_log_odds, size_t threads) {
    if (cells.cells.empty()) return;
    if (threads > 1)
        return apply_frame_cells_split(tree, cells, extents, occupied_log_odds, threads, split_depth_for(cells.box));
    const uint64_t *first = cells.cells.data(), *last = first + cells.cells.size();
    bool created = false;
    BoundedNode *root = tree.root_for_update(created);
    CellUpdate(tree, extents, occupied_log_odds).apply(root, 0, created, first, last);
}

}  // namespace octoprox
