// The amortized broad phase of paper IV.A: a binary AABB tree over a set of
// boxes (octree cells), built in linear time from Morton codes and improved
// a little during every query instead of being built well up front.
//
// * build(): Morton codes of the box centres on a 2^k lattice over their
//   tight bounds, an LSD radix sort, then the binary radix tree of the
//   sorted codes (the split of every node is where its common prefix ends),
//   linked by one stack pass and boxed bottom-up in the same pass.  O(n).
// * refine(steps): each step walks one root-to-leaf path, chosen by the
//   bits of a counter as in the paper, and at each node on it applies the
//   child/grandchild rotation that most lowers the surface area of the
//   tree.  O(depth) per step, no allocation, and every step leaves a valid
//   tree (each node's box is exactly the union of its children's).
// * Queries never allocate: a fixed stack of kMaxDepth + 2 entries, which
//   the build (depth <= 96) and the rotations (depth capped) respect.
//
// Nodes live in one flat array: internal nodes first, then the leaves.
//
// Measured (tests/unit/test_box_tree.cpp): on the geb079 map (143,729
// cells) the SAH cost is 1.25x the median-split tree's after the build,
// <= 1.10x after 128 steps and 0.73x at convergence; on the paper's synthetic
// scene the Morton tree starts at 0.94x and converges to 0.90x.
#pragma once

#include "base/lazy_value.hpp"
#include "broadphase/radix_sort.hpp"
#include "geometry/aabb.hpp"

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>
#include <vector>

namespace octoprox {

struct BoxTreeNode {
    Aabb box;
    int32_t left = -1;    // children; -1 for a leaf
    int32_t right = -1;
    int32_t parent = -1;  // -1 for the root
    int32_t item = -1;    // leaf: index of its box in the build input
    int32_t height = 0;   // edges on the longest path down to a leaf
    bool is_leaf() const { return left < 0; }
};

// Deepest leaf (edges from the root) any tree state may have.
constexpr int kBoxTreeMaxDepth = 120;

struct BoxTreeOptions {
    int morton_bits = 10;  // lattice bits per axis, 1..21
    int digit_bits = 8;    // radix sort digit: 8 or 11 bits
    // Rotations never make a leaf deeper than this (clamped to
    // [1, kBoxTreeMaxDepth]); the build itself is at most 96 deep.
    int max_depth = kBoxTreeMaxDepth;
};

// Surface-area cost of a tree, normalised by the root's area: the expected
// number of inner nodes and of leaves a random ray (or small query) through
// the root visits.  The leaf term is the same for every tree over the same
// boxes (one box a leaf); the inner term is what tree quality changes.
struct SahCost {
    double inner = 0.0;
    double leaves = 0.0;
    double total() const { return inner + leaves; }
};

class BoxTree {
public:
    static constexpr int kMaxDepth = kBoxTreeMaxDepth;
    static constexpr int kStackSize = kMaxDepth + 2;

    // Items are the indices of `boxes`.  Reuses every buffer: rebuilding
    // with no more boxes than before allocates nothing.
    void build(const Aabb *boxes, size_t count, const BoxTreeOptions &options = BoxTreeOptions());
    void build(const std::vector<Aabb> &boxes, const BoxTreeOptions &options = BoxTreeOptions()) {
        build(boxes.data(), boxes.size(), options);
    }
    void clear();

    // Spends `steps` path walks improving the tree; returns the rotations
    // applied.  Each rotation strictly lowers the surface-area cost.
    uint32_t refine(uint32_t steps);
    uint64_t refine_steps_done() const { return path_counter_; }

    SahCost sah() const;
    double sah_cost() const { return sah().total(); }
    // The same cost of the median-split AabbTree over the same boxes,
    // computed on first use after each build (O(n log n), allocates: a
    // diagnostic, not for the query path; computing it in build() would
    // make the build ~12x slower).  Concurrent calls are safe: the first
    // computes, the others wait for it.
    SahCost reference_sah() const;
    // sah_cost() / reference total: 1 means as good as the median split.
    double sah_ratio() const { return sah_cost() / reference_sah().total(); }

    bool empty() const { return nodes_.empty(); }
    size_t item_count() const { return nodes_.empty() ? 0 : (nodes_.size() + 1) / 2; }
    size_t node_count() const { return nodes_.size(); }
    int32_t root() const { return root_; }
    const BoxTreeNode &node(int32_t index) const { return nodes_[index]; }
    int height() const { return nodes_.empty() ? 0 : nodes_[root_].height; }

    // Calls visit(item) for every leaf whose box `node_test` accepts, after
    // every ancestor's box passed too.  visit may return bool: false stops
    // the traversal (and the function returns false).
    template <class NodeTest, class Visit>
    bool for_each_leaf_if(NodeTest &&node_test, Visit &&visit) const;
    // Leaves whose box overlaps `query` (closed boxes, like Aabb::overlaps).
    template <class Visit>
    bool for_each_overlap(const Aabb &query, Visit &&visit) const {
        return for_each_leaf_if([&query](const Aabb &box) { return box.overlaps(query); },
                                std::forward<Visit>(visit));
    }

    // Nearest-first depth-first search for distance engines: visits leaves
    // whose lower bound lower_bound(box) (e.g. a squared distance) is at
    // most the current bound, entering the nearer child first.  visit(item,
    // leaf_lower_bound) returns the new bound (return a negative bound to
    // stop).  Returns the final bound.
    template <class LowerBound, class Visit>
    double for_each_by_distance(LowerBound &&lower_bound, double bound, Visit &&visit) const;
    // The same with the squared distance to a box as the lower bound.
    template <class Visit>
    double for_each_by_distance(const Aabb &query, double squared_bound, Visit &&visit) const {
        return for_each_by_distance([&query](const Aabb &box) { return box.squared_distance(query); },
                                    squared_bound, std::forward<Visit>(visit));
    }

private:
    void build_nodes(const Aabb *boxes, size_t count, const BoxTreeOptions &options);
    SahCost median_split_sah() const;
    void compute_codes(const Aabb *boxes, size_t count, int morton_bits);
    void make_leaves(const Aabb *boxes);
    void link_radix_tree();
    uint32_t split_level(size_t gap) const;
    void finish_node(int32_t index);
    bool rotate_best(int32_t index, int depth);
    void swap_subtrees(int32_t a, int32_t b);

    std::vector<BoxTreeNode> nodes_;
    int32_t root_ = -1;
    uint64_t path_counter_ = 0;
    int max_depth_ = kMaxDepth;
    LazyValue<SahCost> reference_;
    // Build buffers, kept so that rebuilds allocate nothing.
    std::vector<uint64_t> codes_;
    std::vector<uint32_t> order_;
    RadixScratch scratch_;
    RadixSortOptions sort_options_;
};

template <class NodeTest, class Visit>
bool BoxTree::for_each_leaf_if(NodeTest &&node_test, Visit &&visit) const {
    if (nodes_.empty()) return true;
    // Depth-first with both children pushed: at most one pending sibling per
    // level plus the two children of the deepest node.
    int32_t stack[kStackSize];
    int top = 0;
    stack[top++] = root_;
    while (top > 0) {
        const BoxTreeNode &n = nodes_[stack[--top]];
        if (!node_test(n.box)) continue;
        if (!n.is_leaf()) {
            stack[top++] = n.right;
            stack[top++] = n.left;
            continue;
        }
        if constexpr (std::is_same_v<decltype(visit(n.item)), bool>) {
            if (!visit(n.item)) return false;
        } else {
            visit(n.item);
        }
    }
    return true;
}

template <class LowerBound, class Visit>
double BoxTree::for_each_by_distance(LowerBound &&lower_bound, double bound, Visit &&visit) const {
    if (nodes_.empty()) return bound;
    struct Entry {
        int32_t node;
        double lower;
    };
    Entry stack[kStackSize];
    int top = 0;
    stack[top++] = Entry{root_, lower_bound(nodes_[root_].box)};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.lower > bound) continue;  // the bound may have shrunk since the push
        const BoxTreeNode &n = nodes_[e.node];
        if (n.is_leaf()) {
            bound = visit(n.item, e.lower);
            continue;
        }
        Entry near{n.left, lower_bound(nodes_[n.left].box)};
        Entry far{n.right, lower_bound(nodes_[n.right].box)};
        if (far.lower < near.lower) std::swap(near, far);
        if (far.lower <= bound) stack[top++] = far;
        if (near.lower <= bound) stack[top++] = near;
    }
    return bound;
}

}  // namespace octoprox
