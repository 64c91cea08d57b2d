#include "octree/decay.hpp"

#include "octree/bounded_tree.hpp"

namespace octoprox {
namespace {

class Decay {
public:
    Decay(BoundedOcTree &tree, double amount, float occupied) : tree_(tree), amount_(amount), occupied_(occupied) {}

    // Whether the node goes.
    bool visit(BoundedNode *node) {
        if (!node->has_child_array()) return decay_leaf(node);
        for (unsigned int i = 0; i < 8; ++i) {
            if (!tree_.nodeChildExists(node, i) || !visit(tree_.getNodeChild(node, i))) continue;
            tree_.remove_child(node, i);
            removed_ = true;
        }
        if (!node->has_child_array()) return true;
        if (!tree_.pruneNode(node)) node->updateOccupancyChildren();
        return false;
    }

    bool removed() const { return removed_; }

private:
    bool decay_leaf(BoundedNode *leaf) {
        const float next = decayed_log_odds(leaf->getLogOdds(), amount_);
        if (next == 0.0f) return true;
        leaf->setLogOdds(next);
        if (!(next >= occupied_)) leaf->set_point_extent(0);
        return false;
    }

    BoundedOcTree &tree_;
    const double amount_;
    const float occupied_;
    bool removed_ = false;
};

}  // namespace

bool decay_cells(BoundedOcTree &tree, double amount, float occupied_log_odds) {
    BoundedNode *root = tree.getRoot();
    if (root == nullptr) return false;
    Decay decay(tree, amount, occupied_log_odds);
    if (decay.visit(root)) {
        tree.clear();
        return true;
    }
    return decay.removed();
}

}  // namespace octoprox
