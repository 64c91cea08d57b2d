#include "broadphase/cell_boxes.hpp"

#include "octree/sensor_octree.hpp"
#include "query/octree_cell.hpp"

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
    CellExtractor(const OctreeView &view, const CellBands &bands, CellBoxes &occupied,
                  CellBoxes *uncertain)
        : view_(view), bands_(bands), occupied_(occupied), uncertain_(uncertain),
          // With no uncertain output, only obstacle leaves matter.
          lowest_wanted_(uncertain != nullptr ? bands.free_log_odds : bands.threshold_log_odds) {}

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
        if (l >= bands_.threshold_log_odds) occupied_.add(cell_box(key, view_.resolution()), key, l);
        else if (uncertain_ != nullptr) uncertain_->add(cell_box(key, view_.resolution()), key, l);
    }

private:
    const OctreeView &view_;
    const CellBands &bands_;
    CellBoxes &occupied_;
    CellBoxes *uncertain_;
    float lowest_wanted_;
};

}  // namespace

void extract_cell_boxes(const OctreeView &view, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain) {
    occupied.clear();
    if (uncertain != nullptr) uncertain->clear();
    if (OctreeView::NodeRef root = view.root())
        CellExtractor(view, bands, occupied, uncertain).visit(root, CellKey{});
}

void extract_cell_boxes(const SensorOctree &tree, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain) {
    extract_cell_boxes(tree.view(), bands, occupied, uncertain);
}

}  // namespace octoprox
