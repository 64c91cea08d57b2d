#include "query/cost_collector.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "octree/sensor_octree.hpp"
#include "robot/linkset.hpp"

#include <algorithm>
#include <tuple>

namespace octoprox {
namespace {

auto order_key(uint32_t link, const CellKey &c) {
    return std::make_tuple(link, c.depth, c.key[0], c.key[1], c.key[2]);
}

}  // namespace

void CostCollector::offer(const PlacedShape &shape, const CellKey &key, bool unknown, float log_odds,
                          const Aabb &cell, const CollisionSettings &settings, uint64_t &narrow_tests) {
    const Aabb part = unknown ? cell.intersection(settings.region) : cell;
    if (!part.has_volume()) return;
    if (!shape_touches_cell(shape, part.center(), part.half_extent(), narrow_tests)) return;
    const double p = unknown ? settings.unknown_probability : probability_from_log_odds(log_odds);
    add(shape.link, key, unknown ? kUnknown : kUncertain, p, part);
}

void CostCollector::add(uint32_t link, const CellKey &cell, int cell_class, double probability,
                        const Aabb &region) {
    pairs_.push_back(Pair{link, cell, cell_class, probability, region});
}

CostSummary CostCollector::finish(const std::vector<Aabb> &link_boxes, uint32_t keep, std::vector<CostBox> &out,
                                  bool keep_flat) {
    // One box per (link, cell), however many shapes of the link touch it.
    std::sort(pairs_.begin(), pairs_.end(), [](const Pair &a, const Pair &b) {
        return order_key(a.link, a.cell) < order_key(b.link, b.cell);
    });
    pairs_.erase(std::unique(pairs_.begin(), pairs_.end(),
                             [](const Pair &a, const Pair &b) {
                                 return order_key(a.link, a.cell) == order_key(b.link, b.cell);
                             }),
                 pairs_.end());
    out.clear();
    for (const Pair &p : pairs_) {
        CostBox box;
        box.box = p.region.intersection(link_boxes[p.link]);
        if (!keep_flat && !box.box.has_volume()) continue;  // no volume: no box
        box.probability = p.probability;
        box.link = p.link, box.cell_class = p.cell_class, box.cell = p.cell;
        out.push_back(box);
    }
    return keep_costliest(out, keep);
}

CostSummary keep_costliest(std::vector<CostBox> &boxes, uint32_t keep) {
    CostSummary summary;
    for (CostBox &box : boxes) {
        box.cost = box.probability * box.box.volume();
        summary.total += box.cost;
    }
    summary.box_count = boxes.size();
    const size_t kept = std::min<size_t>(keep, boxes.size());
    std::partial_sort(boxes.begin(), boxes.begin() + kept, boxes.end(),
                      [](const CostBox &a, const CostBox &b) { return a.cost > b.cost; });
    boxes.resize(kept);
    return summary;
}

void CostCollector::mark_links(std::vector<uint8_t> &wanted) const {
    for (const Pair &p : pairs_) wanted[p.link] = 1;
}

// Only the links with pairs: an exact mesh box places the mesh.
void link_boxes(const LinkSet &links, const CostCollector &cost, std::vector<Aabb> &out) {
    out.assign(links.link_count(), Aabb());
    std::vector<uint8_t> wanted(links.link_count(), 0);
    cost.mark_links(wanted);
    for (const PlacedShape &shape : links.placed())
        if (wanted[shape.link]) out[shape.link].grow(shape.exact_box());
}

}  // namespace octoprox
