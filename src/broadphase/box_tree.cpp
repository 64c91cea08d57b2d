#include "broadphase/box_tree.hpp"

#include "broadphase/aabb_tree.hpp"
#include "broadphase/morton.hpp"

#include <algorithm>
#include <stdexcept>

namespace octoprox {
namespace {

// Candidate split levels run from 0 to 95 (64 code bits, then 32 bits of
// sorted position for equal codes), and the build stack holds strictly
// increasing levels, so it never holds more than 96 entries.
constexpr int kBuildStackSize = 128;

Aabb merged(const Aabb &a, const Aabb &b) {
    Aabb m = a;
    m.grow(b);
    return m;
}

// Refinement only applies a rotation that lowers the area by more than this
// share of the rotated node's area, so rounding can never make it cycle.
constexpr double kMinGain = 1e-9;

}  // namespace

void BoxTree::clear() {
    nodes_.clear();
    root_ = -1;
    path_counter_ = 0;
    reference_.reset();
}

// A build that throws (out of memory) leaves an empty tree, never nodes
// half written that a later walk would follow.
void BoxTree::build(const Aabb *boxes, size_t count, const BoxTreeOptions &options) {
    try {
        build_nodes(boxes, count, options);
    } catch (...) {
        clear();
        throw;
    }
}

void BoxTree::build_nodes(const Aabb *boxes, size_t count, const BoxTreeOptions &options) {
    // Node indices are int32_t and sort payloads uint32_t.
    if (count > (size_t{1} << 30)) throw std::length_error("BoxTree: too many boxes");
    root_ = -1;
    path_counter_ = 0;
    reference_.reset();
    max_depth_ = std::clamp(options.max_depth, 1, kMaxDepth);
    // Every node is written below: resize() without clear() keeps the old
    // nodes instead of value-initialising 2n of them first.
    nodes_.resize(count == 0 ? 0 : 2 * count - 1);
    if (count == 0) return;
    compute_codes(boxes, count, options.morton_bits);
    sort_options_.digit_bits = options.digit_bits;
    radix_sort(codes_, order_, scratch_, sort_options_);
    make_leaves(boxes);
    if (count == 1) {
        root_ = 0;
        return;
    }
    link_radix_tree();
}

// Codes of the box centres on the lattice over the centres' tight bounds
// (tighter than the boxes' bounds: the lattice is spent where centres are).
void BoxTree::compute_codes(const Aabb *boxes, size_t count, int morton_bits) {
    Aabb centres;
    for (size_t i = 0; i < count; ++i) centres.grow(boxes[i].center());
    const MortonQuantizer quantizer(centres, morton_bits);
    sort_options_.key_bits = quantizer.code_bits();
    codes_.resize(count);
    order_.resize(count);
    for (size_t i = 0; i < count; ++i) {
        codes_[i] = quantizer.encode(boxes[i].center());
        order_[i] = static_cast<uint32_t>(i);
    }
}

// Leaf of sorted position i is node (n - 1) + i; inner nodes are 0..n-2.
void BoxTree::make_leaves(const Aabb *boxes) {
    const size_t first_leaf = codes_.size() - 1;
    for (size_t i = 0; i < codes_.size(); ++i) {
        BoxTreeNode &leaf = nodes_[first_leaf + i];
        leaf = BoxTreeNode();
        leaf.item = static_cast<int32_t>(order_[i]);
        leaf.box = boxes[order_[i]];
    }
}

// The level at which sorted neighbours `gap` and `gap + 1` part: the length
// of their common code prefix, or, for equal codes, 64 plus the common
// prefix of their positions (Karras' tie break, which splits runs of equal
// codes in halves).
uint32_t BoxTree::split_level(size_t gap) const {
    const uint64_t diff = codes_[gap] ^ codes_[gap + 1];
    if (diff != 0) return static_cast<uint32_t>(__builtin_clzll(diff));
    const uint32_t positions = static_cast<uint32_t>(gap) ^ static_cast<uint32_t>(gap + 1);
    return 64 + static_cast<uint32_t>(__builtin_clz(positions));
}

// The binary radix tree of the sorted codes is the Cartesian tree of the
// split levels of the n - 1 gaps between neighbours: a node's range splits at
// its gap with the shortest common prefix (unique in the range because the
// codes are sorted and, with the tie break, distinct).  The classic stack
// construction builds it left to right in O(n): the stack holds the right
// spine, whose levels strictly increase.  A node popped off the stack has
// both subtrees complete, so its box is computed right there: that is the
// bottom-up box pass.
void BoxTree::link_radix_tree() {
    const size_t gaps = codes_.size() - 1;
    const auto first_leaf = static_cast<int32_t>(gaps);
    int32_t spine[kBuildStackSize];
    uint32_t spine_level[kBuildStackSize];
    int top = 0;
    for (size_t gap = 0; gap < gaps; ++gap) {
        const uint32_t level = split_level(gap);
        const auto index = static_cast<int32_t>(gap);
        int32_t popped = -1;
        while (top > 0 && spine_level[top - 1] >= level) {
            popped = spine[--top];
            finish_node(popped);
        }
        BoxTreeNode &n = nodes_[index];
        n = BoxTreeNode();
        n.left = popped >= 0 ? popped : first_leaf + index;
        n.right = first_leaf + index + 1;  // replaced if a later gap hangs below
        if (top > 0) nodes_[spine[top - 1]].right = index;
        spine[top] = index;
        spine_level[top] = level;
        ++top;
    }
    while (top > 0) finish_node(spine[--top]);
    root_ = spine[0];
}

// Box, height and child links of a node whose children are final.
void BoxTree::finish_node(int32_t index) {
    BoxTreeNode &n = nodes_[index];
    const BoxTreeNode &l = nodes_[n.left];
    const BoxTreeNode &r = nodes_[n.right];
    n.box = merged(l.box, r.box);
    n.height = 1 + std::max(l.height, r.height);
    nodes_[n.left].parent = index;
    nodes_[n.right].parent = index;
}

uint32_t BoxTree::refine(uint32_t steps) {
    if (nodes_.size() < 5) {  // fewer than 3 leaves: nothing to rotate
        path_counter_ += steps;
        return 0;
    }
    uint32_t rotations = 0;
    int32_t path[kMaxDepth + 1];
    for (uint32_t step = 0; step < steps; ++step) {
        // The path: bit d of the counter picks the child at depth d, so
        // successive steps spread over the tree like a bit-reversed count,
        // covering every node of depth d within 2^d steps.
        const uint64_t bits = path_counter_++;
        int depth = 0;
        for (int32_t index = root_; !nodes_[index].is_leaf(); ++depth) {
            path[depth] = index;
            if (rotate_best(index, depth)) ++rotations;
            const BoxTreeNode &n = nodes_[index];
            index = ((bits >> (depth & 63)) & 1) ? n.right : n.left;
        }
        // Rotations below changed heights on the path (boxes of path nodes
        // never change: a rotation keeps the rotated node's leaf set).
        for (int d = depth - 1; d >= 0; --d) {
            BoxTreeNode &n = nodes_[path[d]];
            n.height = 1 + std::max(nodes_[n.left].height, nodes_[n.right].height);
        }
    }
    return rotations;
}

// Kensler's tree rotations at `index` (children A, B; grandchildren A1, A2,
// B1, B2): exchanging a child with a grandchild on the other side (4 ways)
// or two grandchildren across (2 ways).  The node's own box is unchanged;
// only the changed children's areas count.  Applies the best one if it
// lowers the area and keeps the subtree within the depth cap.
bool BoxTree::rotate_best(int32_t index, int depth) {
    const BoxTreeNode &n = nodes_[index];
    const BoxTreeNode &a = nodes_[n.left];
    const BoxTreeNode &b = nodes_[n.right];
    const double area_a = a.box.surface_area(), area_b = b.box.surface_area();
    const int max_height = max_depth_ - depth;
    double best_gain = kMinGain * n.box.surface_area();
    int32_t swap_x = -1, swap_y = -1;
    auto consider = [&](int32_t x, int32_t y, double gain, int height) {
        if (gain > best_gain && height <= max_height) {
            best_gain = gain;
            swap_x = x;
            swap_y = y;
        }
    };
    auto h = [&](int32_t i) { return nodes_[i].height; };
    // A exchanged with a child of B: B keeps the other child and takes A.
    if (!b.is_leaf()) {
        consider(n.left, b.left, area_b - merged(a.box, nodes_[b.right].box).surface_area(),
                 2 + std::max({h(b.left) - 1, h(n.left), h(b.right)}));
        consider(n.left, b.right, area_b - merged(a.box, nodes_[b.left].box).surface_area(),
                 2 + std::max({h(b.right) - 1, h(n.left), h(b.left)}));
    }
    if (!a.is_leaf()) {
        consider(n.right, a.left, area_a - merged(b.box, nodes_[a.right].box).surface_area(),
                 2 + std::max({h(a.left) - 1, h(n.right), h(a.right)}));
        consider(n.right, a.right, area_a - merged(b.box, nodes_[a.left].box).surface_area(),
                 2 + std::max({h(a.right) - 1, h(n.right), h(a.left)}));
    }
    // Grandchildren exchanged across: both children change.
    if (!a.is_leaf() && !b.is_leaf()) {
        const Aabb &a1 = nodes_[a.left].box, &a2 = nodes_[a.right].box;
        const Aabb &b1 = nodes_[b.left].box, &b2 = nodes_[b.right].box;
        const int hg = 2 + std::max({h(a.left), h(a.right), h(b.left), h(b.right)});
        consider(a.left, b.left,
                 area_a + area_b - merged(b1, a2).surface_area() - merged(a1, b2).surface_area(), hg);
        consider(a.left, b.right,
                 area_a + area_b - merged(b2, a2).surface_area() - merged(b1, a1).surface_area(), hg);
    }
    if (swap_x < 0) return false;
    swap_subtrees(swap_x, swap_y);
    return true;
}

// Exchanges two subtrees that are not ancestors of each other, then refits
// their (new) parents, deepest first, so every box stays exact.
void BoxTree::swap_subtrees(int32_t x, int32_t y) {
    const int32_t px = nodes_[x].parent, py = nodes_[y].parent;
    int32_t &slot_x = nodes_[px].left == x ? nodes_[px].left : nodes_[px].right;
    int32_t &slot_y = nodes_[py].left == y ? nodes_[py].left : nodes_[py].right;
    slot_x = y;
    slot_y = x;
    nodes_[x].parent = py;
    nodes_[y].parent = px;
    // One parent may be the other's parent (child/grandchild exchange):
    // refit the lower one first.
    const bool py_below_px = nodes_[py].parent == px;
    finish_node(py_below_px ? py : px);
    finish_node(py_below_px ? px : py);
}

SahCost BoxTree::sah() const {
    SahCost cost;
    if (nodes_.empty()) return cost;
    for (const BoxTreeNode &n : nodes_) (n.is_leaf() ? cost.leaves : cost.inner) += n.box.surface_area();
    const double root_area = nodes_[root_].box.surface_area();
    if (root_area > 0.0) {
        cost.inner /= root_area;
        cost.leaves /= root_area;
    }
    return cost;
}

SahCost BoxTree::reference_sah() const {
    return reference_.get([this] { return median_split_sah(); });
}

SahCost BoxTree::median_split_sah() const {
    SahCost cost;
    if (nodes_.empty()) return cost;
    std::vector<Aabb> boxes(item_count());
    for (const BoxTreeNode &n : nodes_)
        if (n.is_leaf()) boxes[n.item] = n.box;
    AabbTree median;
    median.build(boxes);
    for (size_t i = 0; i < median.size(); ++i) {
        const AabbTreeNode &n = median.node(static_cast<int32_t>(i));
        (n.is_leaf() ? cost.leaves : cost.inner) += n.box.surface_area();
    }
    const double root_area = median.node(median.root()).box.surface_area();
    if (root_area > 0.0) {
        cost.inner /= root_area;
        cost.leaves /= root_area;
    }
    return cost;
}

}  // namespace octoprox
