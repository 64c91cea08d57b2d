// Settings and outputs of distance queries.
#pragma once

#include "geometry/pose.hpp"
#include "octree/octree_view.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace octoprox {

struct DistanceSettings {
    float threshold_log_odds = 0.0f;  // obstacle when a cell's log-odds >= this
    bool unknown_occupied = false;
    double abs_err = 0.0;  // the answer may exceed the minimum by max(abs_err,
    double rel_err = 0.0;  // rel_err * answer); 0 and 0: exact
    double cutoff = std::numeric_limits<double>::infinity();  // farther: "at least cutoff"
    bool signed_distance = false;  // penetration depth as a negative distance
    bool point_extents = false;    // obstacle leaves are their point extents (octree_cell.hpp)
    // Per-link queries only: each link's own cutoff (one per link; the
    // smaller of it and `cutoff` applies), so a link that can only move a
    // little is searched only that far.  Its per-link answer is then at
    // most its cutoff ("at least" when nothing is nearer).  A negative
    // cutoff skips the link (its answer stays infinity).
    const std::vector<double> *link_cutoffs = nullptr;
};

// The closest pair found: a shape of a link and an obstacle cell.
struct DistanceOutcome {
    bool found = false;  // an obstacle lies within the cutoff
    double distance = std::numeric_limits<double>::infinity();  // 0 when touching
    Vec3 on_link = Vec3::Zero();  // witness on the padded shape, map frame
    Vec3 on_cell = Vec3::Zero();  // witness on the cell, map frame
    uint32_t link = 0, shape = 0;
    int32_t attached = -1;  // the shape's attached object (PlacedShape::attached)
    CellKey cell;
    bool cell_unknown = false;
    float cell_log_odds = 0.0f;
    int64_t box_index = -1;  // caller boxes (AmortizedEngine::bind_boxes): the closest box
    uint64_t narrow_tests = 0;
};

}  // namespace octoprox
