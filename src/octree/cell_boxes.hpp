// The paper's T_{1,1}: the boxes of the octree cells a broad phase manages,
// read off a sensor octree (occupied cells for collision and distance,
// uncertain cells and unknown cubes for cost, paper IV.C, and unknown
// cubes as obstacles when unknown space counts as occupied).
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
    // An obstacle leaf's box is its point extent when it keeps one (the
    // query engines' obstacle_bounds, octree_cell.hpp), else its cube.
    bool point_extents = false;
};

// Fills `occupied` with the leaves at or above the threshold and, unless
// null, `uncertain` with the leaves in the uncertain band (both cleared
// first), in depth-first child order; keys are the cells', boxes the
// obstacle boxes (bands.point_extents).  Subtrees whose maximum log-odds (an
// inner node's value) is below the lowest band wanted are skipped.  Boxes
// are exact: the same faces as the query engines' cell boxes.
void extract_cell_boxes(const OctreeView &view, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain);
void extract_cell_boxes(const SensorOctree &tree, const CellBands &bands, CellBoxes &occupied,
                        CellBoxes *uncertain);
// Only the uncertain band (cleared first): what a cost query adds to a
// context already holding the obstacle cells.
void extract_uncertain_boxes(const OctreeView &view, const CellBands &bands, CellBoxes &uncertain);

// Fills `unknown` (cleared first) with the unknown cubes: every missing
// child of an inner node, at its own depth and size, or the whole map cube
// when the map is empty; log-odds 0.  Unknown space is bounded by the map
// cube, as in the query engines (octree/octree_cell.hpp).
void extract_unknown_boxes(const OctreeView &view, CellBoxes &unknown);

}  // namespace octoprox
