#include "octree/cell_boxes.hpp"

#include "octree/octree_cell.hpp"
#include "octree/sensor_octree.hpp"

namespace octoprox {

void CellBoxes::clear() {
    boxes.clear();
    keys.clear();
    log_odds.clear();
}

void CellBoxes::add(const Aabb &box, const CellKey &key, float cell_log_odds) {
    boxes.push_back(box);
    keys.push_back(key);
    log_odds.push_back(cell_log_odds);
}

namespace {

class CellExtractor {
public:
    // Either output may be null (not wanted).
    CellExtractor(const OctreeView &view, const CellBands &bands, CellBoxes *occupied, CellBoxes *uncertain)
        : view_(view), bands_(bands), occupied_(occupied), uncertain_(uncertain),
          // With no uncertain output, only obstacle leaves matter.
          lowest_wanted_(uncertain != nullptr ? bands.free_log_odds : bands.threshold_log_odds) {
        model_.point_extents = bands.point_extents;
        model_.threshold = bands.threshold_log_odds;
        model_.pad = obstacle_box_pad(view.resolution());
    }

    // Recursion depth is bounded by kTreeDepth.
    void visit(OctreeView::NodeRef node, const CellKey &key) {
        const float l = view_.log_odds(node);
        // An inner node holds the maximum of its children: below the lowest
        // band, no leaf under it is wanted.
        if (l < lowest_wanted_) return;
        if (view_.has_children(node)) {
            view_.prefetch_children(node, 0xFFu);
            for (int i = 0; i < 8; ++i)
                if (OctreeView::NodeRef child = view_.child(node, i)) visit(child, key.child(i));
            return;
        }
        const bool obstacle = l >= bands_.threshold_log_odds;
        CellBoxes *band = obstacle ? occupied_ : uncertain_;
        if (band == nullptr) return;
        const Aabb cube = cell_box(key, view_.resolution());
        band->add(obstacle ? obstacle_bounds(view_, node, cube, model_, false) : cube, key, l);
    }

private:
    const OctreeView &view_;
    const CellBands &bands_;
    CellBoxes *occupied_;
    CellBoxes *uncertain_;
    float lowest_wanted_;
    ObstacleModel model_;  // leaves only: no inner boxes
};

}  // namespace

void extract_cell_boxes(const OctreeView &view, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain) {
    occupied.clear();
    if (uncertain != nullptr) uncertain->clear();
    if (OctreeView::NodeRef root = view.root())
        CellExtractor(view, bands, &occupied, uncertain).visit(root, CellKey{});
}

void extract_uncertain_boxes(const OctreeView &view, const CellBands &bands, CellBoxes &uncertain) {
    uncertain.clear();
    if (OctreeView::NodeRef root = view.root())
        CellExtractor(view, bands, nullptr, &uncertain).visit(root, CellKey{});
}

namespace {

// Recursion depth is bounded by kTreeDepth.
void add_missing_children(const OctreeView &view, OctreeView::NodeRef node, const CellKey &key,
                          CellBoxes &unknown) {
    if (!view.has_children(node)) return;
    for (int i = 0; i < 8; ++i) {
        const CellKey child_key = key.child(i);
        if (OctreeView::NodeRef child = view.child(node, i)) add_missing_children(view, child, child_key, unknown);
        else unknown.add(cell_box(child_key, view.resolution()), child_key, 0.0f);
    }
}

}  // namespace

void extract_unknown_boxes(const OctreeView &view, CellBoxes &unknown) {
    unknown.clear();
    const OctreeView::NodeRef root = view.root();
    if (root == nullptr) unknown.add(cell_box(CellKey{}, view.resolution()), CellKey{}, 0.0f);
    else add_missing_children(view, root, CellKey{}, unknown);
}

void extract_cell_boxes(const SensorOctree &tree, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain) {
    extract_cell_boxes(tree.view(), bands, occupied, uncertain);
}

}  // namespace octoprox
