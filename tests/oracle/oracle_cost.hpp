// The brute-force cost oracle (compute_cost = 1, query.h and the paper's
// section IV.C): every (link, cell) pair where some padded shape of the link
// touches a cell that is neither known free nor an obstacle:
//   uncertain: a known cell with free_threshold <= p < the request's
//              threshold (float log-odds, as the obstacle rule), whole;
//   unknown:   an unknown cube (unknown space free only), clipped to the
//              region: the request's, or by default the bounds of all
//              observed cells (computed here from the known leaves).
// Its box is the (clipped) cell intersected with the link's bounding box
// (the union of the link's enabled padded shapes' axis-aligned bounds,
// computed here from the shape descriptions), its cost probability x volume
// (unknown: the request's unknown_probability).
#pragma once

#include "oracle_boxes.hpp"
#include "oracle_cells.hpp"
#include "oracle_index.hpp"

#include <map>
#include <utility>
#include <vector>

namespace oracle {

struct CostSettings {
    float threshold_log_odds = 0.0f;  // obstacle at or above
    float free_log_odds = 0.0f;       // free below
    bool unknown_occupied = false;
    double unknown_probability = 0.5;
    AlignedBox region;                // where unknown space counts
};

struct CostPair {
    uint32_t link = 0;
    const MapCell *cell = nullptr;
    AlignedBox box;  // clipped cell x link bounds (may be inverted when they only touch within 1e-9)
    double probability = 0.0;
    double cost = 0.0;
    int32_t cell_class = OPX_CELL_UNKNOWN;
};

using LinkCell = std::pair<uint32_t, CellKey>;

struct CostAnswer {
    std::map<LinkCell, CostPair> pairs;      // certainly touched
    std::map<LinkCell, CostPair> ambiguous;  // touched within the ambiguity band only
    double total = 0.0;                      // over `pairs`
    double ambiguous_total = 0.0;
};

// Bounds of the link's enabled padded shapes, one per link (empty, lo > hi,
// for a link with none), from the specs and link poses.
std::vector<AlignedBox> link_bounds(const RobotSpec &robot);

// The bounds of the known leaves' boxes; `empty` when there is none.
AlignedBox known_bounds(const std::vector<opx_leaf> &leaves, bool &empty);

CostAnswer oracle_cost(const RobotSpec &robot, const std::vector<PlacedShape> &placed, const CellIndex &cells,
                       const CostSettings &settings);

}  // namespace oracle
