#include "query/cost_pipeline.hpp"

#include <algorithm>
#include <tuple>

namespace octoprox {
namespace {

auto cell_order(const CellKey &c) { return std::make_tuple(c.depth, c.key[0], c.key[1], c.key[2]); }

}  // namespace

CostSummary CostPipeline::finish(const LinkSet &links, CostCollector &pairs, uint32_t keep,
                                 std::vector<CostBox> &out) {
    link_boxes(links, pairs, link_boxes_);
    return pairs.finish(link_boxes_, keep, out);
}

// Boxes of no volume are kept here: another waypoint may grow them.
void CostPipeline::add_waypoint(const LinkSet &links, CostCollector &pairs) {
    link_boxes(links, pairs, link_boxes_);
    pairs.finish(link_boxes_, UINT32_MAX, waypoint_boxes_, true);
    merged_.insert(merged_.end(), waypoint_boxes_.begin(), waypoint_boxes_.end());
}

// Each cell counted once: its box is the bounding box of every box the
// path's waypoints and links made in it (all inside the cell).
CostSummary CostPipeline::finish_path(uint32_t keep, std::vector<CostBox> &out) {
    std::stable_sort(merged_.begin(), merged_.end(),
                     [](const CostBox &a, const CostBox &b) { return cell_order(a.cell) < cell_order(b.cell); });
    out.clear();
    for (const CostBox &box : merged_) {
        if (!out.empty() && cell_order(out.back().cell) == cell_order(box.cell)) {
            out.back().box.grow(box.box);
            continue;
        }
        out.push_back(box);
    }
    // Cells whose merged box still has no volume give no box.
    out.erase(std::remove_if(out.begin(), out.end(), [](const CostBox &b) { return !b.box.has_volume(); }),
              out.end());
    return keep_costliest(out, keep);
}

}  // namespace octoprox
