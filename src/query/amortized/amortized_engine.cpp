// The amortized engine's queries: per robot shape over the bound trees,
// with the direct engine's exact kernels and contact rules.
#include "query/amortized/amortized_engine.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "narrowphase/shape_distance.hpp"
#include "narrowphase/shape_penetration.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {

// One shape against one band: boxes first, the shape's own cull, then the
// exact test.  Contacts follow the direct engine's rules (max_contacts,
// truncated).  Returns true when the query is done.
template <class Describe>
bool AmortizedEngine::collide_band(const Band &band, const PlacedShape &shape, const CollisionSettings &settings,
                                   std::vector<Contact> &contacts, CollisionOutcome &out, Describe &&describe) {
    bool done = false;
    band.tree.for_each_leaf_if(
        [&](const Aabb &box) { return box.overlaps(shape.box) && shape_may_touch(shape, box); },
        [&](int32_t item) {
            const Aabb &cell = band.cells.boxes[item];
            if (!shape_touches_cell(shape, cell.center(), cell.half_extent(), out.narrow_tests)) return true;
            out.collided = true;
            if (contacts.size() >= settings.max_contacts) {
                out.truncated = settings.max_contacts > 0;
                return !(done = true);
            }
            Contact c;
            c.link = shape.link, c.shape = shape.shape;
            describe(band, item, c);
            if (settings.penetration) set_contact_penetration(shape, cell, c);
            contacts.push_back(c);
            if (contacts.size() >= settings.max_contacts && settings.max_contacts <= 1) done = true;
            return !done;
        });
    return done;
}

template <class Describe>
CollisionOutcome AmortizedEngine::collide_bound(const LinkSet &links, const CollisionSettings &settings,
                                                bool with_unknown, std::vector<Contact> &contacts,
                                                Describe &&describe) {
    contacts.clear();
    CollisionOutcome out;
    bool done = false;
    for (const PlacedShape &shape : links.placed()) {
        if (done || shape.box.empty()) continue;
        done = collide_band(obstacles_, shape, settings, contacts, out, describe);
        if (!done && with_unknown) done = collide_band(unknown_, shape, settings, contacts, out, describe);
    }
    refine(obstacles_);
    if (with_unknown) refine(unknown_);
    return out;
}

// One shape nearest-first over one band, bounded by `bound` (the best
// answer so far, per link when per_link is given).  A signed query in
// contact goes on through every box the shape may overlap (lower bound 0)
// for the deepest penetration, as the direct engine does.
template <class Describe>
void AmortizedEngine::distance_band(const Band &band, const PlacedShape &shape, const DistanceSettings &settings,
                                    std::vector<double> *per_link, double &bound, DistanceOutcome &best,
                                    Describe &&describe) {
    const bool signed_distance = settings.signed_distance;
    if (!signed_distance && bound <= 0.0) return;  // nothing is nearer than touching
    const auto tree_bound = [&] { return signed_distance ? std::max(bound, 0.0) : bound; };
    band.tree.for_each_by_distance(
        [&](const Aabb &box) { return std::max(std::sqrt(shape.box.squared_distance(box)), shape_lower_bound(shape, box)); },
        tree_bound(), [&](int32_t item, double) {
            const Aabb &cell = band.cells.boxes[item];
            ShapeCellDistance d;
            // Signed: a touching cell (distance 0) must still be found once in contact.
            const double limit = signed_distance ? std::max(bound, 1e-300) : bound;
            if (!shape_cell_distance(shape, cell.center(), cell.half_extent(), limit, d, best.narrow_tests))
                return tree_bound();
            if (signed_distance && d.distance <= 0.0) {
                const ShapePenetration p = shape_penetration(shape, cell.center(), cell.half_extent());
                if (-p.depth >= bound) return tree_bound();
                d.distance = -p.depth, d.on_shape = p.on_link, d.on_cell = p.on_cell;
            }
            bound = d.distance;
            if (per_link) (*per_link)[shape.link] = d.distance;
            if (!best.found || d.distance < best.distance) {
                best.found = true, best.distance = d.distance, best.on_link = d.on_shape, best.on_cell = d.on_cell;
                best.link = shape.link, best.shape = shape.shape;
                describe(band, item, best);
            }
            if (signed_distance) return tree_bound();
            return bound <= 0.0 ? -1.0 : bound;
        });
}

template <class Describe>
DistanceOutcome AmortizedEngine::distance_bound(const LinkSet &links, const DistanceSettings &settings,
                                                bool with_unknown, std::vector<double> *per_link,
                                                Describe &&describe) {
    if (per_link) per_link->assign(links.link_count(), std::numeric_limits<double>::infinity());
    DistanceOutcome best;
    for (const PlacedShape &shape : links.placed()) {
        if (shape.box.empty()) continue;
        double bound = per_link ? std::min((*per_link)[shape.link], settings.cutoff)
                                : std::min(best.found ? best.distance : settings.cutoff, settings.cutoff);
        distance_band(obstacles_, shape, settings, per_link, bound, best, describe);
        if (with_unknown) distance_band(unknown_, shape, settings, per_link, bound, best, describe);
        // Touching settles an unsigned overall minimum; signed looks for the deepest.
        if (!per_link && !settings.signed_distance && best.found && best.distance <= 0.0) break;
    }
    refine(obstacles_);
    if (with_unknown) refine(unknown_);
    return best;
}

CollisionOutcome AmortizedEngine::collide(const SensorOctree &tree, const LinkSet &links,
                                          const CollisionSettings &settings, std::vector<Contact> &contacts) {
    bind(tree, settings.threshold_log_odds);
    if (settings.unknown_occupied || settings.cost) bind_unknown(tree);
    if (settings.cost) bind_uncertain(tree, settings.threshold_log_odds, settings.free_log_odds);
    const double res = tree.params().resolution;
    CollisionOutcome out = collide_bound(
        links, settings, settings.unknown_occupied, contacts, [&](const Band &band, int32_t item, Contact &c) {
            const CellKey &key = band.cells.keys[item];
            for (int axis = 0; axis < 3; ++axis) c.center[axis] = key.center(axis, res);
            c.size = key.size(res);
            const float l = band.cells.log_odds[item];
            c.cell_class = band.unknown ? kUnknown : tree.classify_log_odds(l);
            c.probability = band.unknown ? 0.5 : probability_from_log_odds(l);
        });
    cost_.clear();
    if (settings.cost) collect_cost(links, settings, out.narrow_tests);
    return out;
}

DistanceOutcome AmortizedEngine::distance(const SensorOctree &tree, const LinkSet &links,
                                          const DistanceSettings &settings, std::vector<double> *per_link) {
    bind(tree, settings.threshold_log_odds);
    if (settings.unknown_occupied) bind_unknown(tree);
    return distance_bound(links, settings, settings.unknown_occupied, per_link,
                          [&](const Band &band, int32_t item, DistanceOutcome &best) {
                              best.cell = band.cells.keys[item];
                              best.cell_unknown = band.unknown;
                              best.cell_log_odds = band.unknown ? 0.0f : band.cells.log_odds[item];
                          });
}

CollisionOutcome AmortizedEngine::collide_boxes(const LinkSet &links, const CollisionSettings &settings,
                                                std::vector<Contact> &contacts) {
    return collide_bound(links, settings, false, contacts, [&](const Band &band, int32_t item, Contact &c) {
        const Aabb &box = band.cells.boxes[item];
        for (int axis = 0; axis < 3; ++axis) c.center[axis] = box.center()[axis];
        c.size = box.longest_edge();
        c.cell_class = kOccupied;
        c.probability = 1.0;
    });
}

DistanceOutcome AmortizedEngine::distance_boxes(const LinkSet &links, const DistanceSettings &settings,
                                                std::vector<double> *per_link) {
    return distance_bound(links, settings, false, per_link,
                          [&](const Band &, int32_t item, DistanceOutcome &best) { best.box_index = item; });
}

}  // namespace octoprox
