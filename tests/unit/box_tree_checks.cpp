#include "box_tree_checks.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

namespace unit {

using octoprox::Aabb;
using octoprox::BoxTree;
using octoprox::BoxTreeNode;
using octoprox::Vec3;

namespace {

bool same_box(const Aabb &a, const Aabb &b) { return a.lo == b.lo && a.hi == b.hi; }

std::string problem(const char *what, int32_t node) {
    std::ostringstream out;
    out << what << " (node " << node << ")";
    return out.str();
}

// Checks one inner node's links, box and height against its children.
std::string check_inner(const BoxTree &tree, int32_t index) {
    const BoxTreeNode &n = tree.node(index);
    const int32_t size = static_cast<int32_t>(tree.node_count());
    if (n.right < 0 || n.left >= size || n.right >= size) return problem("bad child index", index);
    const BoxTreeNode &l = tree.node(n.left), &r = tree.node(n.right);
    if (l.parent != index || r.parent != index) return problem("child's parent link is wrong", index);
    Aabb box = l.box;
    box.grow(r.box);
    if (!same_box(box, n.box)) return problem("box is not the union of the children's", index);
    if (n.height != 1 + std::max(l.height, r.height)) return problem("wrong height", index);
    return std::string();
}

}  // namespace

std::string check_tree(const BoxTree &tree, const std::vector<Aabb> &boxes) {
    if (boxes.empty()) return tree.empty() ? std::string() : "tree of no boxes is not empty";
    if (tree.node_count() != 2 * boxes.size() - 1) return "node count is not 2n - 1";
    if (tree.node(tree.root()).parent != -1) return "root has a parent";
    std::vector<int> seen(boxes.size(), 0);
    // Depth-first with explicit depths: each node reached once means a tree.
    std::vector<std::pair<int32_t, int>> stack{{tree.root(), 0}};
    size_t reached = 0;
    while (!stack.empty()) {
        const auto [index, depth] = stack.back();
        stack.pop_back();
        if (++reached > tree.node_count()) return "cycle: more nodes reached than exist";
        if (depth > BoxTree::kMaxDepth) return problem("leaf deeper than kMaxDepth", index);
        const BoxTreeNode &n = tree.node(index);
        if (n.is_leaf()) {
            if (n.item < 0 || size_t(n.item) >= boxes.size()) return problem("bad item", index);
            if (seen[n.item]++) return problem("item in two leaves", index);
            if (!same_box(n.box, boxes[n.item])) return problem("leaf box differs from its item's", index);
            if (n.height != 0) return problem("leaf height not 0", index);
            continue;
        }
        const std::string inner = check_inner(tree, index);
        if (!inner.empty()) return inner;
        stack.push_back({n.left, depth + 1});
        stack.push_back({n.right, depth + 1});
    }
    if (reached != tree.node_count()) return "some nodes are not reachable from the root";
    return std::string();
}

std::vector<int32_t> brute_overlaps(const std::vector<Aabb> &boxes, const Aabb &query) {
    std::vector<int32_t> items;
    for (size_t i = 0; i < boxes.size(); ++i)
        if (boxes[i].overlaps(query)) items.push_back(static_cast<int32_t>(i));
    return items;
}

std::vector<int32_t> tree_overlaps(const BoxTree &tree, const Aabb &query) {
    std::vector<int32_t> items;
    tree.for_each_overlap(query, [&](int32_t item) { items.push_back(item); });
    std::sort(items.begin(), items.end());
    return items;
}

double brute_nearest(const std::vector<Aabb> &boxes, const Aabb &query) {
    double best = std::numeric_limits<double>::infinity();
    for (const Aabb &b : boxes) best = std::min(best, b.squared_distance(query));
    return best;
}

double tree_nearest(const BoxTree &tree, const Aabb &query) {
    return tree.for_each_by_distance(query, std::numeric_limits<double>::infinity(),
                                     [](int32_t, double squared) { return squared; });
}

std::vector<Aabb> random_queries(size_t n, const Aabb &region, double min_edge, double max_edge,
                                 std::mt19937_64 &rng) {
    std::uniform_real_distribution<double> unit_interval(0.0, 1.0), edge(min_edge, max_edge);
    std::vector<Aabb> queries;
    for (size_t i = 0; i < n; ++i) {
        Vec3 centre;
        for (int axis = 0; axis < 3; ++axis)
            centre[axis] = region.lo[axis] + unit_interval(rng) * (region.hi[axis] - region.lo[axis]);
        queries.push_back(Aabb::from_center(centre, Vec3::Constant(0.5 * edge(rng))));
    }
    return queries;
}

uint64_t nodes_tested(const BoxTree &tree, const std::vector<Aabb> &queries) {
    uint64_t tested = 0;
    for (const Aabb &q : queries)
        tree.for_each_leaf_if([&](const Aabb &box) { return ++tested, box.overlaps(q); }, [](int32_t) {});
    return tested;
}

uint64_t nodes_tested(const octoprox::AabbTree &tree, const std::vector<Aabb> &queries) {
    uint64_t tested = 0;
    std::vector<int32_t> stack;
    for (const Aabb &q : queries) {
        stack.assign(1, tree.root());
        while (!stack.empty()) {
            const octoprox::AabbTreeNode &n = tree.node(stack.back());
            stack.pop_back();
            ++tested;
            if (!n.box.overlaps(q) || n.is_leaf()) continue;
            stack.push_back(n.right);
            stack.push_back(n.left);
        }
    }
    return tested;
}

namespace {

constexpr int kBins = 16;

struct Bin {
    Aabb box;
    size_t count = 0;
};

// Best binned split of items [begin, end): returns the split position after
// partitioning, or begin + (end - begin) / 2 when no bin split separates.
size_t binned_split(std::vector<int32_t> &items, size_t begin, size_t end, const std::vector<Aabb> &boxes) {
    Aabb centres;
    for (size_t i = begin; i < end; ++i) centres.grow(boxes[items[i]].center());
    double best_cost = std::numeric_limits<double>::infinity();
    int best_axis = -1, best_bin = 0;
    auto bin_of = [&](int32_t item, int axis) {
        const double extent = centres.hi[axis] - centres.lo[axis];
        const int bin = int(kBins * (boxes[item].center()[axis] - centres.lo[axis]) / extent);
        return std::min(bin, kBins - 1);
    };
    for (int axis = 0; axis < 3; ++axis) {
        if (!(centres.hi[axis] > centres.lo[axis])) continue;
        Bin bins[kBins];
        for (size_t i = begin; i < end; ++i) {
            Bin &b = bins[bin_of(items[i], axis)];
            b.box.grow(boxes[items[i]]);
            ++b.count;
        }
        double right_area[kBins];
        Aabb right;
        size_t right_count = 0;
        for (int b = kBins - 1; b > 0; --b) {
            right.grow(bins[b].box);
            right_count += bins[b].count;
            right_area[b] = double(right_count) * right.surface_area();
        }
        Aabb left;
        size_t left_count = 0;
        for (int b = 1; b < kBins; ++b) {
            left.grow(bins[b - 1].box);
            left_count += bins[b - 1].count;
            const double cost = double(left_count) * left.surface_area() + right_area[b];
            if (left_count > 0 && left_count < end - begin && cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_bin = b;
            }
        }
    }
    if (best_axis < 0) return begin + (end - begin) / 2;
    const auto middle = std::partition(items.begin() + begin, items.begin() + end,
                                       [&](int32_t item) { return bin_of(item, best_axis) < best_bin; });
    return size_t(middle - items.begin());
}

// Sum of node areas of the subtree over items [begin, end), into cost.
Aabb binned_build(std::vector<int32_t> &items, size_t begin, size_t end, const std::vector<Aabb> &boxes,
                  octoprox::SahCost &cost) {
    if (end - begin == 1) {
        cost.leaves += boxes[items[begin]].surface_area();
        return boxes[items[begin]];
    }
    const size_t middle = binned_split(items, begin, end, boxes);
    Aabb box = binned_build(items, begin, middle, boxes, cost);
    box.grow(binned_build(items, middle, end, boxes, cost));
    cost.inner += box.surface_area();
    return box;
}

}  // namespace

octoprox::SahCost binned_sah_cost(const std::vector<Aabb> &boxes) {
    octoprox::SahCost cost;
    if (boxes.empty()) return cost;
    std::vector<int32_t> items(boxes.size());
    for (size_t i = 0; i < items.size(); ++i) items[i] = int32_t(i);
    const double root_area = binned_build(items, 0, items.size(), boxes, cost).surface_area();
    cost.inner /= root_area;
    cost.leaves /= root_area;
    return cost;
}

}  // namespace unit
