#include "query/amortized.hpp"

#include "query/narrow_phase.hpp"
#include "query/shape_distance.hpp"

#include <chrono>
#include <cmath>

namespace octoprox {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

}  // namespace

void AmortizedEngine::bind(const SensorOctree &tree, float threshold_log_odds) {
    if (!caller_boxes_ && builds_ > 0 && bound_identity_ == tree.identity() &&
        bound_generation_ == tree.generation() && bound_threshold_ == threshold_log_odds)
        return;
    const auto start = Clock::now();
    CellBands bands;
    bands.threshold_log_odds = threshold_log_odds;
    bands.free_log_odds = threshold_log_odds;
    extract_cell_boxes(tree, bands, cells_, nullptr);
    extract_ms_ = ms_since(start);
    build_tree();
    caller_boxes_ = false;
    bound_identity_ = tree.identity(), bound_generation_ = tree.generation();
    bound_threshold_ = threshold_log_odds;
}

// T_{1,1} is the copy of the caller's boxes here.
void AmortizedEngine::bind_boxes(std::vector<Aabb> boxes) {
    const auto start = Clock::now();
    cells_.clear();
    cells_.boxes = std::move(boxes);
    extract_ms_ = ms_since(start);
    build_tree();
    caller_boxes_ = true;
    bound_identity_ = 0;  // no octree has identity 0: the next octree query binds
}

void AmortizedEngine::build_tree() {
    const auto start = Clock::now();
    BoxTreeOptions options;
    options.morton_bits = options_.morton_bits;
    tree_.build(cells_.boxes, options);
    build_ms_ = ms_since(start);
    ++builds_;
}

AmortizedStats AmortizedEngine::stats() const {
    return AmortizedStats{cells_.boxes.size(), builds_, tree_.refine_steps_done(), extract_ms_, build_ms_};
}

// Each enabled shape against the box tree: boxes first, the shape's own
// cull, then the exact test.  Contacts follow the direct engine's rules.
template <class Describe>
CollisionOutcome AmortizedEngine::collide_bound(const LinkSet &links, const CollisionSettings &settings,
                                                std::vector<Contact> &contacts, Describe &&describe) {
    contacts.clear();
    CollisionOutcome out;
    bool done = false;
    for (const PlacedShape &shape : links.placed()) {
        if (done || shape.box.empty()) continue;
        tree_.for_each_leaf_if(
            [&](const Aabb &box) { return box.overlaps(shape.box) && shape_may_touch(shape, box); },
            [&](int32_t item) {
                const Aabb &cell = cells_.boxes[item];
                if (!shape_touches_cell(shape, cell.center(), cell.half_extent(), out.narrow_tests)) return true;
                out.collided = true;
                if (contacts.size() >= settings.max_contacts) {
                    out.truncated = settings.max_contacts > 0;
                    return !(done = true);
                }
                Contact c;
                c.link = shape.link, c.shape = shape.shape;
                describe(item, c);
                contacts.push_back(c);
                if (contacts.size() >= settings.max_contacts && settings.max_contacts <= 1) done = true;
                return !done;
            });
    }
    refine();
    return out;
}

// Each enabled shape nearest-first over the box tree, bounded by the
// best answer so far (per link when per_link is given).
template <class Describe>
DistanceOutcome AmortizedEngine::distance_bound(const LinkSet &links, const DistanceSettings &settings,
                                                std::vector<double> *per_link, Describe &&describe) {
    if (per_link) per_link->assign(links.link_count(), std::numeric_limits<double>::infinity());
    DistanceOutcome best;
    for (const PlacedShape &shape : links.placed()) {
        if (shape.box.empty()) continue;
        double bound = per_link ? std::min((*per_link)[shape.link], settings.cutoff)
                                : std::min(best.found ? best.distance : settings.cutoff, settings.cutoff);
        tree_.for_each_by_distance(
            [&](const Aabb &box) { return std::max(std::sqrt(shape.box.squared_distance(box)), shape_lower_bound(shape, box)); },
            bound, [&](int32_t item, double) {
                const Aabb &cell = cells_.boxes[item];
                ShapeCellDistance d;
                if (!shape_cell_distance(shape, cell.center(), cell.half_extent(), bound, d, best.narrow_tests)) return bound;
                bound = d.distance;
                if (per_link) (*per_link)[shape.link] = d.distance;
                if (!best.found || d.distance < best.distance) {
                    best.found = true, best.distance = d.distance, best.on_link = d.on_shape, best.on_cell = d.on_cell;
                    best.link = shape.link, best.shape = shape.shape;
                    describe(item, best);
                }
                return bound <= 0.0 ? -1.0 : bound;
            });
        if (!per_link && best.found && best.distance <= 0.0) break;
    }
    refine();
    return best;
}

CollisionOutcome AmortizedEngine::collide(const SensorOctree &tree, const LinkSet &links,
                                          const CollisionSettings &settings, std::vector<Contact> &contacts) {
    bind(tree, settings.threshold_log_odds);
    const double res = tree.params().resolution;
    return collide_bound(links, settings, contacts, [&](int32_t item, Contact &c) {
        const CellKey &key = cells_.keys[item];
        for (int axis = 0; axis < 3; ++axis) c.center[axis] = key.center(axis, res);
        c.size = key.size(res);
        c.cell_class = tree.classify_log_odds(cells_.log_odds[item]);
        c.probability = probability_from_log_odds(cells_.log_odds[item]);
    });
}

DistanceOutcome AmortizedEngine::distance(const SensorOctree &tree, const LinkSet &links,
                                          const DistanceSettings &settings, std::vector<double> *per_link) {
    bind(tree, settings.threshold_log_odds);
    return distance_bound(links, settings, per_link, [&](int32_t item, DistanceOutcome &best) {
        best.cell = cells_.keys[item];
        best.cell_unknown = false, best.cell_log_odds = cells_.log_odds[item];
    });
}

CollisionOutcome AmortizedEngine::collide_boxes(const LinkSet &links, const CollisionSettings &settings,
                                                std::vector<Contact> &contacts) {
    return collide_bound(links, settings, contacts, [&](int32_t item, Contact &c) {
        const Aabb &box = cells_.boxes[item];
        for (int axis = 0; axis < 3; ++axis) c.center[axis] = box.center()[axis];
        c.size = box.longest_edge();
        c.cell_class = kOccupied;
        c.probability = 1.0;
    });
}

DistanceOutcome AmortizedEngine::distance_boxes(const LinkSet &links, const DistanceSettings &settings,
                                                std::vector<double> *per_link) {
    return distance_bound(links, settings, per_link,
                          [&](int32_t item, DistanceOutcome &best) { best.box_index = item; });
}

}  // namespace octoprox
