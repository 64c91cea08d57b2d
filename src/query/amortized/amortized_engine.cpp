// The amortized engine's queries: per robot shape over the bound trees,
// with the direct engine's exact kernels and contact rules.
#include "query/amortized/amortized_engine.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "query/cell_description.hpp"
#include "query/contact_sink.hpp"
#include "query/nearest_pair.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {

// One shape against one band: boxes first, the shape's own cull, then the
// contact sink's exact test, until the obstacle answer is settled.
template <class Describe>
void AmortizedEngine::collide_band(const Band &band, const PlacedShape &shape, ContactSink &sink,
                                   Describe &&describe) {
    band.tree.for_each_leaf_if(
        [&](const Aabb &box) { return box.overlaps(shape.box) && shape_may_touch(shape, box); },
        [&](int32_t item) { return !sink.offer(shape, band.cells.boxes[item], [&] { return describe(band, item); }); });
}

template <class Describe>
CollisionOutcome AmortizedEngine::collide_bound(const LinkSet &links, const CollisionSettings &settings,
                                                bool with_unknown, std::vector<Contact> &contacts,
                                                Describe &&describe) {
    CollisionOutcome out;
    ContactSink sink(settings, contacts, out);
    for (const PlacedShape &shape : links.placed()) {
        if (sink.settled() || shape.box.empty()) continue;
        collide_band(obstacles_, shape, sink, describe);
        if (!sink.settled() && with_unknown) collide_band(unknown_, shape, sink, describe);
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
            ShapeCellDistance d;
            if (!nearer_pair(shape, band.cells.boxes[item], bound, signed_distance, d, best.narrow_tests))
                return tree_bound();
            bound = d.distance;
            if (per_link) (*per_link)[shape.link] = d.distance;
            if (keep_if_nearer(shape, d, best)) describe(band, item, best);
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
        if (per_link && settings.link_cutoffs) bound = std::min(bound, (*settings.link_cutoffs)[shape.link]);
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
    bind(tree, settings.threshold_log_odds, settings.point_extents);
    if (settings.unknown_occupied || settings.cost) bind_unknown(tree);
    if (settings.cost) bind_uncertain(tree, settings.threshold_log_odds, settings.free_log_odds);
    CollisionOutcome out =
        collide_bound(links, settings, settings.unknown_occupied, contacts, [&](const Band &band, int32_t item) {
            return describe_cell(tree, band.cells.keys[item], band.unknown, band.cells.log_odds[item]);
        });
    cost_.clear();
    if (settings.cost) collect_cost(links, settings, out.narrow_tests);
    return out;
}

DistanceOutcome AmortizedEngine::distance(const SensorOctree &tree, const LinkSet &links,
                                          const DistanceSettings &settings, std::vector<double> *per_link) {
    bind(tree, settings.threshold_log_odds, settings.point_extents);
    if (settings.unknown_occupied) bind_unknown(tree);
    return distance_bound(links, settings, settings.unknown_occupied, per_link,
                          [&](const Band &band, int32_t item, DistanceOutcome &best) {
                              set_cell(best, band.cells.keys[item], band.unknown, band.cells.log_odds[item]);
                          });
}

CollisionOutcome AmortizedEngine::collide_boxes(const LinkSet &links, const CollisionSettings &settings,
                                                std::vector<Contact> &contacts) {
    return collide_bound(links, settings, false, contacts, [&](const Band &band, int32_t item) {
        return describe_caller_box(band.cells.boxes[item]);
    });
}

DistanceOutcome AmortizedEngine::distance_boxes(const LinkSet &links, const DistanceSettings &settings,
                                                std::vector<double> *per_link) {
    return distance_bound(links, settings, false, per_link,
                          [&](const Band &, int32_t item, DistanceOutcome &best) { best.box_index = item; });
}

}  // namespace octoprox
