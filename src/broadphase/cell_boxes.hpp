// The paper's T_{1,1}: the boxes of the octree cells a broad phase manages,
// read off a sensor octree (occupied cells for collision and distance, and
// uncertain cells for cost, paper IV.C).
#pragma once

#include "geometry/aabb.hpp"
#include "octree/octree_view.hpp"

#include <cstddef>
#include <vector>

namespace octoprox {

class SensorOctree;

// Cells in structure-of-arrays form: boxes[i] is the box of the cell keys[i]
// with log-odds log_odds[i], so `boxes` feeds BoxTree::build directly and a
// tree item indexes all three.
struct CellBoxes {
    std::vector<Aabb> boxes;
    std::vector<CellKey> keys;
    std::vector<float> log_odds;

    size_t size() const { return boxes.size(); }
    // Keeps the capacity: refilling allocates nothing once warm.
    void clear();
    void add(const Aabb &box, const CellKey &key, float cell_log_odds);
};

// Log-odds bands, with the library's conventions: an obstacle when
// log-odds >= threshold; uncertain when free <= log-odds < threshold.
struct CellBands {
    float threshold_log_odds = 0.0f;
    float free_log_odds = 0.0f;
};

// Fills `occupied` with the leaves at or above the threshold and, unless
// null, `uncertain` with the leaves in the uncertain band (both cleared
// first), in depth-first child order.  Subtrees whose maximum log-odds (an
// inner node's value) is below the lowest band wanted are skipped.  Boxes
// are exact: the same faces as the query engines' cell boxes.
void extract_cell_boxes(const OctreeView &view, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain);
void extract_cell_boxes(const SensorOctree &tree, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain);

}  // namespace octoprox
