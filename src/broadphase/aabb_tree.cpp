#include "broadphase/aabb_tree.hpp"

#include <algorithm>
#include <numeric>

namespace octoprox {

void AabbTree::build(const std::vector<Aabb> &item_boxes) {
    nodes_.clear();
    leaves_.clear();
    if (item_boxes.empty()) return;
    nodes_.reserve(2 * item_boxes.size() - 1);
    leaves_.reserve(item_boxes.size());
    std::vector<int32_t> items(item_boxes.size());
    std::iota(items.begin(), items.end(), 0);
    build_range(items, 0, items.size(), item_boxes);
}

// Splits at the median of the box centres along the widest axis of the
// centres: balanced, O(n log n), good enough for robots and meshes.
int32_t AabbTree::build_range(std::vector<int32_t> &items, size_t begin, size_t end,
                              const std::vector<Aabb> &item_boxes) {
    const int32_t index = static_cast<int32_t>(nodes_.size());
    nodes_.emplace_back();
    if (end - begin == 1) {
        leaves_.push_back(index);
        nodes_[index].item = items[begin];
        nodes_[index].box = item_boxes[items[begin]];
        return index;
    }
    Aabb centres;
    for (size_t i = begin; i < end; ++i) centres.grow(item_boxes[items[i]].center());
    int axis = 0;
    (centres.hi - centres.lo).maxCoeff(&axis);
    const size_t middle = begin + (end - begin) / 2;
    std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
                     [&](int32_t a, int32_t b) {
                         return item_boxes[a].center()[axis] < item_boxes[b].center()[axis];
                     });
    const int32_t left = build_range(items, begin, middle, item_boxes);
    const int32_t right = build_range(items, middle, end, item_boxes);
    nodes_[index].left = left;
    nodes_[index].right = right;
    nodes_[index].box = nodes_[left].box;
    nodes_[index].box.grow(nodes_[right].box);
    return index;
}

void AabbTree::refit(const std::vector<Aabb> &item_boxes) {
    for (size_t i = nodes_.size(); i-- > 0;) {
        AabbTreeNode &n = nodes_[i];
        if (n.is_leaf()) {
            n.box = item_boxes[n.item];
        } else {
            n.box = nodes_[n.left].box;
            n.box.grow(nodes_[n.right].box);
        }
    }
}

}  // namespace octoprox
