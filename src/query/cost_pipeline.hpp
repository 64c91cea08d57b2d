// From the (link, cell) cost pairs an engine collected to the cost boxes a
// caller reads (paper IV.C): each pair's part of the cell clipped to its
// link's bounding box, priced (probability x volume), the costliest kept.
// A path merges its waypoints' boxes cell by cell first.
#pragma once

#include "query/cost_collector.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

class LinkSet;

class CostPipeline {
public:
    // One query's pairs (links at their poses then): the `keep` costliest
    // boxes in `out`, costliest first.
    CostSummary finish(const LinkSet &links, CostCollector &pairs, uint32_t keep, std::vector<CostBox> &out);

    // A path: start_path, then each waypoint's pairs (links at that
    // waypoint's poses), then finish_path.
    void start_path() { merged_.clear(); }
    void add_waypoint(const LinkSet &links, CostCollector &pairs);
    CostSummary finish_path(uint32_t keep, std::vector<CostBox> &out);

private:
    std::vector<Aabb> link_boxes_;
    std::vector<CostBox> waypoint_boxes_, merged_;
};

}  // namespace octoprox
