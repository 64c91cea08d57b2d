// The direct engine: the octree as it is, no per-frame preprocessing, for
// collision (direct_collide.hpp) and distance (direct_distance.hpp).
#pragma once

#include "query/direct/direct_collide.hpp"
#include "query/direct/direct_distance.hpp"
#include "query/engine.hpp"

namespace octoprox {

class DirectEngine final : public Engine {
public:
    CollisionOutcome collide(const SensorOctree &tree, const LinkSet &links, const CollisionSettings &settings,
                             std::vector<Contact> &contacts) override {
        return collider_.collide(tree, links, settings, contacts);
    }
    // Per link, one search a link, each bounded by that link's own best.
    DistanceOutcome distance(const SensorOctree &tree, const LinkSet &links, const DistanceSettings &settings,
                             std::vector<double> *per_link) override {
        return per_link ? distance_.run_per_link(tree, links, settings, *per_link)
                        : distance_.run(tree, links, settings);
    }
    CostCollector &cost() override { return collider_.cost(); }
    EngineStats stats() const override { return EngineStats(); }

private:
    DirectCollider collider_;
    DirectDistance distance_;
};

}  // namespace octoprox
