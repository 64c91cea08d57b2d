// The cost oracle of a path (query.h, opx_path_request.compute_cost): the
// uncertain cells (free_threshold <= p < the obstacle threshold, whole) and
// the unknown cubes clipped to the region of interest that some padded
// shape of some waypoint touches.  Each such cell counts ONCE: its box is
// the bounding box of the boxes (counted part of the cell x the link's
// bounding box) of every waypoint and link touching it, its cost
// probability x volume; a cell whose box has no volume gives no box (the
// union is taken first: flat boxes of single waypoints, e.g. of a point
// moving, still grow it).  One configuration is a path of one waypoint.
//
// Touching is decided exactly (oracle_boxes.hpp: distance to a box that
// need not be a cube), with the ambiguity bands of oracle_robot.hpp; a
// pair in the band is kept aside, and the answer is `undecided` only when
// such a pair could change a cell's box or add a cell.
//
// Slivers: an unknown cube whose face lies on the region's boundary meets
// the region in a flat box (zero volume), or in nothing, or in a box 1 ulp
// thick, depending on how the face and the bound were rounded (the default
// region is computed from cell centres and sizes).  Such a cube costs
// nothing either way; whether it is counted is a rounding accident, so the
// oracle only bounds the number of cells: certain <= found <= certain +
// touched slivers.
#pragma once

#include "oracle_boxes.hpp"
#include "oracle_check.hpp"

#include <map>
#include <set>
#include <vector>

namespace oracle {

struct CostRule {
    float threshold_log_odds = 0.0f;  // obstacles: log-odds >= this
    float free_log_odds = 0.0f;       // uncertain: free <= log-odds < threshold
    bool unknown_occupied = false;    // unknown space is then an obstacle, not a cost
    double unknown_probability = 0.5;
    AlignedBox region;                // where unknown space counts

    enum Part { kNone, kPart, kSliver };
    // The part of `cell` that costs (the whole uncertain cell, or the
    // unknown cube clipped to the region, flattened for a sliver) and its
    // probability.
    Part counts(const MapCell &cell, AlignedBox &part, double &probability) const;
};

// The bounds of the known leaves' boxes: the default region.
AlignedBox observed_bounds(const std::vector<opx_leaf> &leaves);

struct SweptCell {
    const MapCell *cell = nullptr;
    bool certain = false;               // some pair surely touches the cell
    AlignedBox box;                     // bounding box of the certain pairs' boxes
    std::vector<AlignedBox> doubtful;   // boxes of pairs in the ambiguity band
    std::set<uint32_t> links;           // links of the certain pairs
    double probability = 0.0;
    double cost() const { return probability * box.volume(); }
};

class SweptCost {
public:
    explicit SweptCost(const CostRule &rule) : rule_(rule) {}
    // One waypoint: every placed shape against every cell near it.
    void add_configuration(const std::vector<PlacedShape> &placed, const CellIndex &cells);

    // The cells some pair surely touches whose box has a volume (the
    // doubtful-only ones excluded).
    std::vector<const SweptCell *> certain_cells() const;
    // An ambiguous pair could add a cell or grow a cell's box.
    bool undecided() const;
    // Sliver cells some shape touches (not in certain_cells()).
    uint64_t touched_slivers() const { return slivers_.size(); }
    bool is_sliver(const CellKey &key) const { return slivers_.count(key) > 0; }
    double total_cost() const;
    uint64_t ambiguous_pairs() const { return ambiguous_pairs_; }

private:
    void add_pair(const PlacedShape &shape, const MapCell &cell, const AlignedBox &part, double probability,
                  const AlignedBox &link_box);

    CostRule rule_;
    std::map<CellKey, SweptCell> cells_;
    std::set<CellKey> slivers_;
    uint64_t ambiguous_pairs_ = 0;
};

}  // namespace oracle
