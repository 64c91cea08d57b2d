#include "oracle_swept_cost.hpp"

#include <algorithm>
#include <limits>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Larger than every ambiguity band: a cell farther than this from a shape's
// padded bounds is surely not touched.
constexpr double kNearMargin = 1e-4;
// Thinner than this, a clipped unknown cube is a sliver (rounding).
constexpr double kSliverThickness = 1e-11;

double box_gap(const AlignedBox &a, const Vec3 &low, const Vec3 &high) {
    return (a.lo - high).cwiseMax(low - a.hi).cwiseMax(0.0).norm();
}

// The link's bounding box: the union of its enabled shapes' padded boxes.
std::map<uint32_t, AlignedBox> link_boxes(const std::vector<PlacedShape> &placed) {
    std::map<uint32_t, AlignedBox> boxes;
    for (const PlacedShape &s : placed) {
        auto found = boxes.find(s.link);
        if (found == boxes.end()) {
            boxes[s.link] = {s.bounds_min, s.bounds_max};
            continue;
        }
        found->second.lo = found->second.lo.cwiseMin(s.bounds_min);
        found->second.hi = found->second.hi.cwiseMax(s.bounds_max);
    }
    return boxes;
}

// As the documented box: the counted part intersected with the link's box
// (a tolerance-touching pair may give an inverted, zero-volume box).
AlignedBox pair_box(const AlignedBox &part, const AlignedBox &link_box) {
    return {part.lo.cwiseMax(link_box.lo), part.hi.cwiseMin(link_box.hi)};
}

bool contains(const AlignedBox &outer, const AlignedBox &inner) {
    return (outer.lo.array() <= inner.lo.array()).all() && (inner.hi.array() <= outer.hi.array()).all();
}

}  // namespace

CostRule::Part CostRule::counts(const MapCell &cell, AlignedBox &part, double &probability) const {
    if (cell.unknown()) {
        if (unknown_occupied) return kNone;
        part = {aligned_box_of(cell.cell).lo.cwiseMax(region.lo), aligned_box_of(cell.cell).hi.cwiseMin(region.hi)};
        const Vec3 thickness = part.hi - part.lo;
        probability = unknown_probability;
        if (thickness.minCoeff() < -kSliverThickness) return kNone;
        if (thickness.minCoeff() > kSliverThickness) return kPart;
        part.hi = part.hi.cwiseMax(part.lo);  // flat
        return kSliver;
    }
    if (cell.log_odds >= threshold_log_odds || cell.log_odds < free_log_odds) return kNone;
    part = aligned_box_of(cell.cell);
    probability = cell.probability;
    return kPart;
}

AlignedBox observed_bounds(const std::vector<opx_leaf> &leaves) {
    AlignedBox box{Vec3::Constant(kInfinity), Vec3::Constant(-kInfinity)};
    for (const opx_leaf &leaf : leaves) {
        const Vec3 center(leaf.center[0], leaf.center[1], leaf.center[2]);
        box.lo = box.lo.cwiseMin(center - Vec3::Constant(0.5 * leaf.size));
        box.hi = box.hi.cwiseMax(center + Vec3::Constant(0.5 * leaf.size));
    }
    return box;
}

void SweptCost::add_configuration(const std::vector<PlacedShape> &placed, const CellIndex &cells) {
    const std::map<uint32_t, AlignedBox> boxes = link_boxes(placed);
    std::vector<uint32_t> near;
    for (const PlacedShape &shape : placed) {
        cells.candidates(shape.bounds_min - Vec3::Constant(kNearMargin),
                         shape.bounds_max + Vec3::Constant(kNearMargin), near);
        for (uint32_t index : near) {
            const MapCell &cell = cells.cells()[index];
            AlignedBox part;
            double probability = 0.0;
            const CostRule::Part kind = rule_.counts(cell, part, probability);
            if (kind == CostRule::kNone || box_gap(part, shape.bounds_min, shape.bounds_max) > kNearMargin) continue;
            if (kind == CostRule::kPart) add_pair(shape, cell, part, probability, boxes.at(shape.link));
            else if (judge(shape, shape_aligned_distance(shape, part)) != Verdict::kClear) slivers_.insert(cell.key);
        }
    }
}

void SweptCost::add_pair(const PlacedShape &shape, const MapCell &cell, const AlignedBox &part, double probability,
                         const AlignedBox &link_box) {
    const Verdict verdict = judge(shape, shape_aligned_distance(shape, part));
    if (verdict == Verdict::kClear) return;
    SweptCell &swept = cells_[cell.key];
    swept.cell = &cell;
    swept.probability = probability;
    const AlignedBox box = pair_box(part, link_box);
    if (verdict == Verdict::kAmbiguous) {
        ++ambiguous_pairs_;
        swept.doubtful.push_back(box);
        return;
    }
    swept.box = swept.certain ? AlignedBox{swept.box.lo.cwiseMin(box.lo), swept.box.hi.cwiseMax(box.hi)} : box;
    swept.certain = true;
    swept.links.insert(shape.link);
}

// A cell whose box has no volume gives no box (query.h).
std::vector<const SweptCell *> SweptCost::certain_cells() const {
    std::vector<const SweptCell *> out;
    for (const auto &entry : cells_) {
        const SweptCell &c = entry.second;
        if (c.certain && (c.box.lo.array() < c.box.hi.array()).all()) out.push_back(&c);
    }
    return out;
}

bool SweptCost::undecided() const {
    for (const auto &entry : cells_) {
        const SweptCell &c = entry.second;
        for (const AlignedBox &box : c.doubtful)
            if (!c.certain || !contains(c.box, box)) return true;
    }
    return false;
}

double SweptCost::total_cost() const {
    double total = 0.0;
    for (const SweptCell *c : certain_cells()) total += c->cost();
    return total;
}

}  // namespace oracle
