#include "query/context.hpp"

#include "base/error.hpp"
#include "query/direct/direct_engine.hpp"

#include <algorithm>
#include <limits>

namespace octoprox {

// The one place an engine is chosen.
QueryContext::QueryContext(const ContextOptions &options) : kind_(options.engine) {
    if (kind_ == EngineKind::kAmortized) {
        auto amortized = std::make_unique<AmortizedEngine>(options.amortized);
        amortized_ = amortized.get();
        engine_ = std::move(amortized);
    } else {
        engine_ = std::make_unique<DirectEngine>();
    }
}

CollisionAnswer QueryContext::collide(const SensorOctree *tree, const LinkSet &links,
                                      const CollisionSettings &settings) {
    CollisionAnswer answer;
    contacts_.clear();
    cost_boxes_.clear();
    if (tree != nullptr) {
        resolution_ = tree->params().resolution;
        answer.outcome = engine_->collide(*tree, links, settings, contacts_);
        if (settings.cost) answer.cost = cost_.finish(links, engine_->cost(), settings.max_cost_boxes, cost_boxes_);
    }
    collide_world(links, settings, answer);
    return answer;
}

DistanceAnswer QueryContext::distance(const SensorOctree *tree, const LinkSet &links,
                                      const DistanceSettings &settings, bool per_link) {
    link_distances_.clear();
    DistanceAnswer answer;
    if (tree != nullptr) {
        answer.outcome = engine_->distance(*tree, links, settings, per_link ? &link_distances_ : nullptr);
        const DistanceOutcome &o = answer.outcome;
        if (o.found) answer.cell = describe_cell(*tree, o.cell, o.cell_unknown, o.cell_log_odds);
    }
    distance_world(links, settings, per_link, answer);
    if (per_link && settings.link_cutoffs)
        for (size_t link = 0; link < link_distances_.size(); ++link) {
            const double cutoff = (*settings.link_cutoffs)[link];
            link_distances_[link] = cutoff < 0.0 ? std::numeric_limits<double>::infinity()
                                                 : std::min(link_distances_[link], cutoff);
        }
    return answer;
}

PathOutcome QueryContext::path(const SensorOctree *tree, const LinkSet &links, const std::vector<Pose> &poses,
                               size_t waypoints, const PathSettings &settings) {
    if (tree != nullptr) resolution_ = tree->params().resolution;
    contacts_.clear();
    world_contacts_.clear();
    return path_.run(PathRequest{tree, world_, links, poses, waypoints, settings}, *engine_, cost_, cost_boxes_);
}

const ObstacleGrid *QueryContext::obstacle_grid(const SensorOctree &tree, float threshold) {
    const GridKey key{tree.identity(), tree.generation(), threshold};
    if (!grid_known_ || key.identity != grid_key_.identity || key.generation != grid_key_.generation ||
        key.threshold != grid_key_.threshold) {
        grid_known_ = false;
        grid_ = tree.obstacle_grid(threshold);
        grid_key_ = key;
        grid_known_ = true;
    }
    return grid_.get();
}

AmortizedEngine &QueryContext::amortized_engine() {
    if (amortized_ == nullptr)
        throw_invalid("query uses OPX_ENGINE_DIRECT; caller boxes need a context made with OPX_ENGINE_AMORTIZED");
    return *amortized_;
}

AmortizedEngine &QueryContext::bound_boxes() {
    AmortizedEngine &engine = amortized_engine();
    if (!engine.holds_caller_boxes())
        throw_invalid("query holds no caller boxes (call opx_query_bind_boxes first; an octree query since "
                      "unbinds them)");
    return engine;
}

void QueryContext::bind_boxes(std::vector<Aabb> boxes) { amortized_engine().bind_boxes(std::move(boxes)); }

CollisionAnswer QueryContext::collide_boxes(const LinkSet &links, const CollisionSettings &settings) {
    AmortizedEngine &engine = bound_boxes();
    CollisionAnswer answer;
    answer.outcome = engine.collide_boxes(links, settings, contacts_);
    cost_boxes_.clear();
    world_contacts_.clear();
    return answer;
}

DistanceAnswer QueryContext::distance_boxes(const LinkSet &links, const DistanceSettings &settings,
                                            bool per_link) {
    AmortizedEngine &engine = bound_boxes();
    link_distances_.clear();
    DistanceAnswer answer;
    answer.outcome = engine.distance_boxes(links, settings, per_link ? &link_distances_ : nullptr);
    const DistanceOutcome &o = answer.outcome;
    if (o.found) answer.cell = describe_caller_box(engine.caller_box(static_cast<size_t>(o.box_index)));
    return answer;
}

}  // namespace octoprox
