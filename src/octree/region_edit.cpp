#include "octree/region_edit.hpp"

#include "octree/bounded_tree.hpp"

#include <algorithm>

namespace octoprox {
namespace {

void grow(CellRange &range, const CellKey &cube) {
    const int32_t last = cube.width_in_cells() - 1;
    const bool empty = range.empty();
    for (int axis = 0; axis < 3; ++axis) {
        range.lo[axis] = empty ? cube.key[axis] : std::min<int32_t>(range.lo[axis], cube.key[axis]);
        range.hi[axis] = empty ? cube.key[axis] + last : std::max<int32_t>(range.hi[axis], cube.key[axis] + last);
    }
}

// The region test and the rules both passes share.
class EditRules {
public:
    EditRules(const CubeRegion &region, const RegionEdit &edit) : region_(region), edit_(edit) {}

    Cover cover(const CellKey &cube) const { return region_.cover(cube); }

    // Whether some finest cell of the cube is in the region.
    bool any_in(const CellKey &cube) const {
        const Cover c = region_.cover(cube);
        if (c != Cover::kPart) return c == Cover::kAll;
        for (int i = 0; i < 8; ++i)
            if (any_in(cube.child(i))) return true;
        return false;
    }

    // A leaf the edit leaves as it is, wherever the region lies in it.
    bool unchanged_leaf(const BoundedNode &leaf) const {
        return edit_.to_free && leaf.getLogOdds() == edit_.free_value && leaf.point_extent() == 0;
    }

    const RegionEdit &edit() const { return edit_; }

private:
    const CubeRegion &region_;
    const RegionEdit edit_;
};

// The dry run: the blocks the edit will allocate.
class BlockCount {
public:
    BlockCount(const BoundedOcTree &tree, const EditRules &rules) : tree_(tree), rules_(rules) {}

    size_t existing(const BoundedNode *node, const CellKey &cube) const {
        if (rules_.cover(cube) != Cover::kPart) return 0;
        if (!node->has_child_array()) return rules_.unchanged_leaf(*node) ? 0 : virtual_node(cube);
        size_t blocks = 0;
        for (unsigned int i = 0; i < 8; ++i) {
            const CellKey child = cube.child(static_cast<int>(i));
            if (tree_.nodeChildExists(node, i)) blocks += existing(tree_.getNodeChild(node, i), child);
            else if (rules_.edit().to_free) blocks += rules_.cover(child) == Cover::kPart ? virtual_node(child) : 0;
        }
        return blocks;
    }

    // A cube the region crosses that is a leaf (expanded) or absent (made,
    // free space): a block when some cell is in, and its children's.
    size_t virtual_node(const CellKey &cube) const {
        if (!rules_.any_in(cube)) return 0;
        size_t blocks = 1;
        for (int i = 0; i < 8; ++i)
            if (rules_.cover(cube.child(i)) == Cover::kPart) blocks += virtual_node(cube.child(i));
        return blocks;
    }

    // The blocks left below an existing node once the region's cells are
    // removed (exact regions: a leaf in part in the region keeps a cell);
    // `survives` tells whether the node stays (a node left without
    // children goes).
    size_t kept(const BoundedNode *node, const CellKey &cube, bool &survives) const {
        const Cover cover = rules_.cover(cube);
        survives = cover != Cover::kAll;
        if (cover == Cover::kAll) return 0;
        if (!node->has_child_array()) return cover == Cover::kPart ? virtual_node(cube) : 0;
        if (cover == Cover::kNone) return all_below(node);
        size_t blocks = 1;
        survives = false;
        for (unsigned int i = 0; i < 8; ++i) {
            if (!tree_.nodeChildExists(node, i)) continue;
            bool child_survives = false;
            blocks += kept(tree_.getNodeChild(node, i), cube.child(static_cast<int>(i)), child_survives);
            survives |= child_survives;
        }
        return survives ? blocks : 0;
    }

private:
    size_t all_below(const BoundedNode *node) const {
        if (!node->has_child_array()) return 0;
        size_t blocks = 1;
        for (unsigned int i = 0; i < 8; ++i)
            if (tree_.nodeChildExists(node, i)) blocks += all_below(tree_.getNodeChild(node, i));
        return blocks;
    }

    const BoundedOcTree &tree_;
    const EditRules &rules_;
};

class Editor {
public:
    enum class Outcome { kSame, kChanged, kRemove };

    Editor(BoundedOcTree &tree, const EditRules &rules) : tree_(tree), rules_(rules) {}

    Outcome visit(BoundedNode *node, const CellKey &cube) {
        const Cover cover = rules_.cover(cube);
        if (cover == Cover::kNone) return Outcome::kSame;
        if (cover == Cover::kAll) return set_whole(node, cube);
        if (!node->has_child_array()) {
            if (rules_.unchanged_leaf(*node) || !rules_.any_in(cube)) return Outcome::kSame;
            tree_.expandNode(node);
        }
        bool changed = false;
        for (unsigned int i = 0; i < 8; ++i) {
            const CellKey child = cube.child(static_cast<int>(i));
            if (tree_.nodeChildExists(node, i)) {
                const Outcome outcome = visit(tree_.getNodeChild(node, i), child);
                if (outcome == Outcome::kRemove) tree_.remove_child(node, i);
                changed |= outcome != Outcome::kSame;
            } else if (rules_.edit().to_free) {
                changed |= fill(node, i, child);
            }
        }
        if (!node->has_child_array()) return Outcome::kRemove;
        if (changed) changed_below(node);
        return changed ? Outcome::kChanged : Outcome::kSame;
    }

    // Free space where the map holds none: child `index` of `parent`, absent.
    bool fill(BoundedNode *parent, unsigned int index, const CellKey &cube) {
        const Cover cover = rules_.cover(cube);
        if (cover == Cover::kNone || (cover == Cover::kPart && !rules_.any_in(cube))) return false;
        BoundedNode *node = tree_.createNodeChild(parent, index);
        fill_node(node, cube, cover);
        return true;
    }

    // A new node (or root) with some cell in the region.
    void fill_node(BoundedNode *node, const CellKey &cube, Cover cover) {
        if (cover == Cover::kAll) {
            set_free(node, cube);
            return;
        }
        for (unsigned int i = 0; i < 8; ++i) fill(node, i, cube.child(static_cast<int>(i)));
        changed_below(node);
    }

    EditedCubes &result() { return result_; }

private:
    Outcome set_whole(BoundedNode *node, const CellKey &cube) {
        if (!rules_.edit().to_free) {
            grow(result_.removed, cube);
            return Outcome::kRemove;
        }
        if (!node->has_child_array() && rules_.unchanged_leaf(*node)) return Outcome::kSame;
        if (node->has_child_array()) tree_.remove_children(node);
        set_free(node, cube);
        return Outcome::kChanged;
    }

    void set_free(BoundedNode *node, const CellKey &cube) {
        node->setLogOdds(rules_.edit().free_value);
        node->set_point_extent(0);
        grow(result_.set_free, cube);
    }

    // As a frame update leaves a node whose children changed.
    void changed_below(BoundedNode *node) {
        if (!tree_.pruneNode(node)) node->updateOccupancyChildren();
    }

    BoundedOcTree &tree_;
    const EditRules &rules_;
    EditedCubes result_;
};

}  // namespace

size_t region_edit_blocks(const BoundedOcTree &tree, const CubeRegion &region, const RegionEdit &edit) {
    const EditRules rules(region, edit);
    const BlockCount count(tree, rules);
    const BoundedNode *root = tree.getRoot();
    if (root != nullptr) return count.existing(root, CellKey{});
    if (!edit.to_free || rules.cover(CellKey{}) != Cover::kPart) return 0;
    return count.virtual_node(CellKey{});
}

size_t blocks_after_removal(const BoundedOcTree &tree, const CubeRegion &region) {
    const RegionEdit edit;  // to unknown
    const EditRules rules(region, edit);
    const BoundedNode *root = tree.getRoot();
    bool survives = false;
    return root == nullptr ? 0 : BlockCount(tree, rules).kept(root, CellKey{}, survives);
}

EditedCubes apply_region_edit(BoundedOcTree &tree, const CubeRegion &region, const RegionEdit &edit) {
    const EditRules rules(region, edit);
    Editor editor(tree, rules);
    const CellKey root_cube{};
    if (tree.getRoot() != nullptr) {
        const Editor::Outcome outcome = editor.visit(tree.getRoot(), root_cube);
        if (outcome == Editor::Outcome::kRemove) tree.clear();
        editor.result().changed = outcome != Editor::Outcome::kSame;
        return editor.result();
    }
    const Cover cover = rules.cover(root_cube);
    if (!edit.to_free || cover == Cover::kNone || (cover == Cover::kPart && !rules.any_in(root_cube)))
        return editor.result();
    bool created = false;
    editor.fill_node(tree.root_for_update(created), root_cube, cover);
    editor.result().changed = true;
    return editor.result();
}

}  // namespace octoprox
