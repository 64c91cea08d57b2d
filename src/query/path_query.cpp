#include "query/path_query.hpp"

#include <algorithm>
#include <tuple>

namespace octoprox {
namespace {

auto cell_order(const CellKey &c) { return std::make_tuple(c.depth, c.key[0], c.key[1], c.key[2]); }

}  // namespace

// A private copy of the link set takes each waypoint's poses, so the
// caller's set stays read-only; it is copied again only when the caller's
// set changed in more than its poses.
LinkSet &PathQuery::posable_copy(const LinkSet &links) {
    if (!copy_ || copy_source_ != links.identity() || copy_->generation() != links.generation()) {
        copy_ = std::make_unique<LinkSet>(links);
        copy_source_ = links.identity();
    }
    return *copy_;
}

void PathQuery::merge_cost(const std::vector<CostBox> &waypoint_boxes) {
    merged_.insert(merged_.end(), waypoint_boxes.begin(), waypoint_boxes.end());
}

// Each cell counted once: its box is the bounding box of every box the
// path's waypoints and links made in it (all inside the cell).
CostSummary PathQuery::finish_cost(uint32_t keep, std::vector<CostBox> &out) {
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
    out.erase(std::remove_if(out.begin(), out.end(),
                             [](const CostBox &b) { return !b.box.has_volume(); }),
              out.end());
    return keep_costliest(out, keep);
}

}  // namespace octoprox
