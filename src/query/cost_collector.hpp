// Cost of uncertain and unknown space (paper IV.C, Fig. 3): the (link,
// cell) pairs where a link overlaps a cell that is neither known free nor
// an obstacle, turned into boxes (cell intersected with the link's bounding
// box), each with the cell's probability and cost = probability x volume.
#pragma once

#include "geometry/aabb.hpp"
#include "octree/octree_view.hpp"
#include "query/collision_types.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

struct CostBox {
    Aabb box;  // map frame
    double probability = 0.0;
    double cost = 0.0;
    uint32_t link = 0;
    int cell_class = 0;
    CellKey cell;
};

struct CostSummary {
    double total = 0.0;       // sum over all boxes
    uint64_t box_count = 0;   // all boxes (the kept ones are the largest)
};

struct PlacedShape;

class CostCollector {
public:
    void clear() { pairs_.clear(); }
    // The cost rule of both engines, for a cost cell (box `cell`) that
    // `shape` may touch: an uncertain cell counts wholly, a cube of unknown
    // space only clipped to settings.region (a cube that only touches the
    // region adds no volume: nothing); the padded shape must touch the part
    // that counts.
    void offer(const PlacedShape &shape, const CellKey &key, bool unknown, float log_odds, const Aabb &cell,
               const CollisionSettings &settings, uint64_t &narrow_tests);
    // `region` is the part of the cell that counts (the cell itself, or
    // its intersection with the region of interest for unknown space).
    void add(uint32_t link, const CellKey &cell, int cell_class, double probability, const Aabb &region);
    // Dedupes the pairs, builds the boxes against each link's bounding box,
    // keeps the `keep` costliest in `out` (costliest first).
    // keep_flat keeps boxes of no volume (a path merges them first).
    CostSummary finish(const std::vector<Aabb> &link_boxes, uint32_t keep, std::vector<CostBox> &out,
                       bool keep_flat = false);
    // Sets wanted[link] for every link some pair involves.
    void mark_links(std::vector<uint8_t> &wanted) const;

private:
    struct Pair {
        uint32_t link;
        CellKey cell;
        int cell_class;
        double probability;
        Aabb region;
    };
    std::vector<Pair> pairs_;
};

// Prices every box (probability x volume), sums them, and keeps the
// `keep` costliest, costliest first.
CostSummary keep_costliest(std::vector<CostBox> &boxes, uint32_t keep);

// Bounding box of each link that has a pair in `cost` (the union of its
// enabled shapes' exact padded boxes: PlacedShape::exact_box); the other
// links' boxes are left empty.
class LinkSet;
void link_boxes(const LinkSet &links, const CostCollector &cost, std::vector<Aabb> &out);

}  // namespace octoprox
