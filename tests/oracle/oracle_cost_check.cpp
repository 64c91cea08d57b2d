#include "oracle_cost_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <sstream>

namespace oracle {
namespace {

constexpr uint64_t kPrintedMismatches = 8;

// Costs are compared relatively, and to 1e-15 m^3 absolutely: the volume of
// a flat box (a cube touching the region) is 0 or a rounding residue.
constexpr double kCostFloor = 1e-15;

bool close(double a, double b, double relative) {
    return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + kCostFloor;
}

std::set<Triple> triples_of(const std::vector<opx_contact> &contacts, double resolution) {
    std::set<Triple> out;
    for (const opx_contact &c : contacts) out.insert({c.link, c.shape, key_of(c.cell_center, c.cell_size, resolution)});
    return out;
}

// Triple has only operator<.
bool same_sets(const std::set<Triple> &a, const std::set<Triple> &b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](const Triple &x, const Triple &y) { return !(x < y) && !(y < x); });
}

std::string describe_box(const opx_cost_box &b) {
    std::ostringstream out;
    out.precision(17);
    out << "box link " << b.link << " class " << b.cell_class << " min (" << b.min[0] << ", " << b.min[1] << ", "
        << b.min[2] << ") max (" << b.max[0] << ", " << b.max[1] << ", " << b.max[2] << ") p " << b.probability
        << " cost " << b.cost << " cell (" << b.cell_center[0] << ", " << b.cell_center[1] << ", "
        << b.cell_center[2] << ") size " << b.cell_size;
    return out.str();
}

// Why the oracle has no pair (link, cell): each shape's distances.
std::string explain(const CostCase &c, const LinkCell &key) {
    std::ostringstream out;
    out.precision(17);
    const MapCell *cell = c.cells->find(key.second);
    if (!cell) return "; not a cell of the oracle's map";
    bool empty = false;
    const AlignedBox clipped = cell->unknown() ? intersect(aligned_box_of(cell->cell), c.settings->region, empty)
                                               : aligned_box_of(cell->cell);
    out << "\n    oracle's cell: class " << cell->cell_class << " p " << cell->probability << (empty ? " (clipped: EMPTY)" : "")
        << " clipped (" << clipped.lo.transpose() << ") - (" << clipped.hi.transpose() << ")";
    for (const PlacedShape &s : *c.placed)
        if (s.link == key.first)
            out << "\n      shape " << s.shape << " (" << kind_name(s.kind) << ") inflation " << s.inflation
                << ": core distance to the clipped cell " << shape_aligned_distance(s, clipped) << ", to the cell "
                << shape_aligned_distance(s, aligned_box_of(cell->cell));
    return out.str();
}

}  // namespace

opx_collision_result CostChecker::ask(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                      const CostVariant &v, bool cost, std::vector<opx_contact> &contacts) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.unknown_policy = v.unknown_policy;
    request.occupancy_threshold = v.threshold;
    request.max_contacts = v.max_contacts;
    request.compute_cost = cost ? 1 : 0;
    request.max_cost_boxes = v.max_cost_boxes;
    request.unknown_probability = v.unknown_probability;
    if (v.region_set)
        for (int k = 0; k < 3; ++k) request.region_min[k] = v.region.lo[k], request.region_max[k] = v.region.hi[k];
    opx_collision_result r = OPX_COLLISION_RESULT_INIT;
    contacts.clear();
    if (opx_query_collide(query, tree, links, &request, &r) != OPX_OK) {
        fail(std::string("opx_query_collide failed: ") + opx_last_error());
        return r;
    }
    for (size_t i = 0; i < r.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        if (opx_query_get_contact(query, i, &contact) == OPX_OK) contacts.push_back(contact);
    }
    return r;
}

bool CostChecker::check(opx_query *query, const opx_octree *tree, const opx_linkset *links, const CostCase &c,
                        const CostVariant &v) {
    ++queries_;
    failed_ = false;
    std::vector<opx_contact> plain_contacts, contacts;
    const opx_collision_result plain = ask(query, tree, links, v, false, plain_contacts);
    const opx_collision_result r = ask(query, tree, links, v, true, contacts);  // last: its boxes stay
    pairs_ += c.oracle->pairs.size();
    for (const auto &entry : c.oracle->pairs) {
        uncertain_ += entry.second.cell_class == OPX_CELL_UNCERTAIN;
        unknown_ += entry.second.cell_class == OPX_CELL_UNKNOWN;
    }
    for (const auto &entry : c.oracle->ambiguous) flat_ += entry.second.cost <= kCostFloor;
    ambiguous_queries_ += !c.oracle->ambiguous.empty();
    collided_ += r.collided, truncated_ += r.truncated;
    check_contacts(c, v, r, contacts, plain, plain_contacts);
    check_totals(c, v, r);
    check_boxes(query, c, v, r);
    return !failed_;
}

void CostChecker::check_totals(const CostCase &c, const CostVariant &v, const opx_collision_result &r) {
    const CostAnswer &o = *c.oracle;
    const double low = o.total, high = o.total + o.ambiguous_total, tolerance = 1e-9 * high + kCostFloor;
    if (r.total_cost < low - tolerance || r.total_cost > high + tolerance)
        mismatch(c, v, "total_cost " + std::to_string(r.total_cost) + ", oracle " + std::to_string(o.total) +
                           (o.ambiguous.empty() ? "" : " (+ ambiguous " + std::to_string(o.ambiguous_total) + ")"));
    if (o.ambiguous.empty() && o.total > 0.0)
        max_relative_error_ = std::max(max_relative_error_, std::abs(r.total_cost - o.total) / o.total);
    if (r.cost_boxes_found < o.pairs.size() || r.cost_boxes_found > o.pairs.size() + o.ambiguous.size())
        mismatch(c, v, "cost_boxes_found " + std::to_string(r.cost_boxes_found) + ", oracle pairs " +
                           std::to_string(o.pairs.size()) + " (+ ambiguous " + std::to_string(o.ambiguous.size()) + ")");
    if (r.cost_box_count != std::min<uint64_t>(v.max_cost_boxes, r.cost_boxes_found))
        mismatch(c, v, "cost_box_count " + std::to_string(r.cost_box_count) + " is not min(max_cost_boxes, found)");
}

void CostChecker::check_boxes(opx_query *query, const CostCase &c, const CostVariant &v,
                              const opx_collision_result &r) {
    std::vector<double> kept;
    for (size_t i = 0; i < r.cost_box_count; ++i) {
        opx_cost_box box = OPX_COST_BOX_INIT;
        if (opx_query_get_cost_box(query, i, &box) != OPX_OK) return mismatch(c, v, "opx_query_get_cost_box failed");
        if (!kept.empty() && box.cost > kept.back()) mismatch(c, v, "boxes not costliest first: " + describe_box(box));
        kept.push_back(box.cost);
        zero_boxes_ += box.cost == 0.0;
        check_box_fields(c, v, box);
    }
    kept_ += kept.size();
    // Ambiguous pairs of cost 0 (flat boxes) may or may not be kept, after
    // all others; other ambiguous pairs leave the multiset undecided.
    for (const auto &entry : c.oracle->ambiguous)
        if (entry.second.cost > kCostFloor) return;
    std::vector<double> costs;
    for (const auto &entry : c.oracle->pairs) costs.push_back(entry.second.cost);
    std::sort(costs.begin(), costs.end(), std::greater<double>());
    costs.resize(std::max(costs.size(), kept.size()), 0.0);
    for (size_t i = 0; i < kept.size(); ++i)
        if (!close(kept[i], costs[i], 1e-9))
            return mismatch(c, v, "kept box " + std::to_string(i) + " costs " + std::to_string(kept[i]) +
                                      ", the oracle's " + std::to_string(i) + "-th costliest " + std::to_string(costs[i]));
}

void CostChecker::check_box_fields(const CostCase &c, const CostVariant &v, const opx_cost_box &box) {
    const LinkCell key{box.link, key_of(box.cell_center, box.cell_size, c.resolution)};
    const auto found = c.oracle->pairs.find(key);
    const CostPair *pair = found != c.oracle->pairs.end() ? &found->second : nullptr;
    if (!pair) {
        const auto other = c.oracle->ambiguous.find(key);
        if (other == c.oracle->ambiguous.end())
            return mismatch(c, v, "a box the oracle does not have (an obstacle, free, or untouched cell?): " +
                                      describe_box(box) + explain(c, key));
        pair = &other->second;
    }
    bool same = box.cell_class == pair->cell_class && box.probability == pair->probability &&
                box.cell_size == pair->cell->size && close(box.cost, pair->cost, 1e-9);
    for (int k = 0; k < 3; ++k)
        same &= std::abs(box.min[k] - pair->box.lo[k]) <= 1e-12 && std::abs(box.max[k] - pair->box.hi[k]) <= 1e-12 &&
                std::abs(box.cell_center[k] - pair->cell->cell.center[k]) <= 1e-9 * pair->cell->size;
    if (same) return;
    std::ostringstream out;
    out.precision(17);
    out << describe_box(box) << "; oracle: class " << pair->cell_class << " min (" << pair->box.lo.transpose()
        << ") max (" << pair->box.hi.transpose() << ") p " << pair->probability << " cost " << pair->cost;
    mismatch(c, v, "box fields differ: " + out.str());
}

void CostChecker::check_contacts(const CostCase &c, const CostVariant &v, const opx_collision_result &with_cost,
                                 const std::vector<opx_contact> &contacts, const opx_collision_result &without_cost,
                                 const std::vector<opx_contact> &plain_contacts) {
    const OracleAnswer &o = *c.contacts;
    if (with_cost.collided != without_cost.collided)
        mismatch(c, v, "collided " + std::to_string(with_cost.collided) + " with cost, " +
                           std::to_string(without_cost.collided) + " without");
    const bool decided = !o.touching.empty() || o.ambiguous.empty();
    if (decided && bool(with_cost.collided) != !o.touching.empty())
        mismatch(c, v, "collided " + std::to_string(with_cost.collided) + ", the collision oracle says " +
                           (o.touching.empty() ? "clear" : "collision"));
    // Obstacles are OCCUPIED (or UNKNOWN) under the octree's own threshold;
    // under a request threshold below it they keep the octree's class.
    for (const opx_contact &contact : contacts)
        if (v.threshold == 0.0 && contact.cell_class != OPX_CELL_OCCUPIED && contact.cell_class != OPX_CELL_UNKNOWN)
            mismatch(c, v, "a contact with a cell of class " + std::to_string(contact.cell_class));
    if (v.max_contacts != UINT32_MAX) return;
    const std::set<Triple> reported = triples_of(contacts, c.resolution);
    if (!same_sets(reported, triples_of(plain_contacts, c.resolution)))
        mismatch(c, v, "the contacts with cost differ from those without");
    for (const auto &entry : o.touching)
        if (!reported.count(entry.first)) mismatch(c, v, "a contact the oracle has is missing with cost");
    for (const Triple &t : reported)
        if (!o.touching.count(t) && !o.ambiguous.count(t)) mismatch(c, v, "a contact the oracle does not have");
}

void CostChecker::mismatch(const CostCase &c, const CostVariant &v, const std::string &what) {
    failed_ = true;
    if (++mismatches_ > kPrintedMismatches) return;
    std::ostringstream out;
    out.precision(17);
    out << "MISMATCH [" << name_ << "] " << c.label << ": " << what << "\n    request: unknown_policy "
        << v.unknown_policy << " threshold " << v.threshold << " max_contacts " << v.max_contacts
        << " max_cost_boxes " << v.max_cost_boxes << " unknown_probability " << v.unknown_probability;
    if (v.region_set) out << " region (" << v.region.lo.transpose() << ") - (" << v.region.hi.transpose() << ")";
    out << "\n    oracle: " << c.oracle->pairs.size() << " pairs, total " << c.oracle->total << ", "
        << c.oracle->ambiguous.size() << " ambiguous\n    robot: global padding " << c.robot->global_padding;
    for (size_t i = 0; i < c.robot->links.size(); ++i) {
        const LinkSpec &link = c.robot->links[i];
        out << "\n      link " << i << (link.enabled ? "" : " DISABLED") << " padding " << link.padding << " pose "
            << describe_pose(link.pose);
        for (const ShapeSpec &s : link.shapes) out << "\n        " << describe_shape(s);
    }
    std::printf("%s\n", out.str().c_str());
}

void CostChecker::fail(const std::string &message) {
    failed_ = true;
    if (++mismatches_ <= kPrintedMismatches) std::printf("MISMATCH [%s] %s\n", name_.c_str(), message.c_str());
}

int CostChecker::finish(double seconds) const {
    std::printf("SUMMARY %s: queries %llu (collided %llu, truncated %llu), oracle pairs %llu (uncertain %llu, "
                "unknown %llu; undecided: touching the region's face %llu), boxes kept %llu (of cost 0: %llu), "
                "queries with undecided pairs %llu, mismatches %llu, "
                "max relative error of total_cost %.3g; %.1f s\n",
                name_.c_str(), (unsigned long long)queries_, (unsigned long long)collided_,
                (unsigned long long)truncated_, (unsigned long long)pairs_, (unsigned long long)uncertain_,
                (unsigned long long)unknown_, (unsigned long long)flat_, (unsigned long long)kept_,
                (unsigned long long)zero_boxes_,
                (unsigned long long)ambiguous_queries_, (unsigned long long)mismatches_, max_relative_error_, seconds);
    return mismatches_ == 0 ? 0 : 1;
}

}  // namespace oracle
