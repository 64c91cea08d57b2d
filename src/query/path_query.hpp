// Path queries: a sequence of waypoints, each a pose per link, checked in
// order with the direct engine, or with a context's amortized engine over
// its trees bound to the frame (paper IV.C: the cost of the unknown space a
// motion sweeps through, from samples of the path).
#pragma once

#include "query/amortized/amortized_engine.hpp"
#include "query/direct/direct_collide.hpp"
#include "query/direct/direct_distance.hpp"

#include <memory>
#include <vector>

namespace octoprox {

struct PathSettings {
    CollisionSettings collision;  // max_contacts is ignored
    bool distance = false;
    DistanceSettings distance_settings;
};

struct PathOutcome {
    int64_t first_collision = -1;  // waypoint index, -1: none
    double min_distance = std::numeric_limits<double>::infinity();
    int64_t min_distance_waypoint = -1;
    CostSummary cost;
    uint64_t narrow_tests = 0;
};

class PathQuery {
public:
    // poses(w) gives waypoint w's link poses (one per link of `links`).
    // With `amortized`, every waypoint runs on that engine (its trees stay
    // bound across the waypoints and paths), else on the direct engine.
    template <class PosesOf>
    PathOutcome run(const SensorOctree &tree, const LinkSet &links, size_t waypoints, PosesOf &&poses_of,
                    const PathSettings &settings, std::vector<CostBox> &boxes,
                    AmortizedEngine *amortized = nullptr);

private:
    LinkSet &posable_copy(const LinkSet &links);
    void merge_cost(const std::vector<CostBox> &waypoint_boxes);
    CostSummary finish_cost(uint32_t keep, std::vector<CostBox> &out);
    CollisionOutcome collide(AmortizedEngine *amortized, const SensorOctree &tree, const LinkSet &links,
                             const CollisionSettings &settings) {
        return amortized ? amortized->collide(tree, links, settings, contacts_)
                         : collider_.collide(tree, links, settings, contacts_);
    }
    DistanceOutcome distance(AmortizedEngine *amortized, const SensorOctree &tree, const LinkSet &links,
                             const DistanceSettings &settings) {
        return amortized ? amortized->distance(tree, links, settings, nullptr) : distance_.run(tree, links, settings);
    }

    std::unique_ptr<LinkSet> copy_;
    uint64_t copy_source_ = 0;  // identity of the set copied
    DirectCollider collider_;
    DirectDistance distance_;
    std::vector<Contact> contacts_;
    std::vector<Aabb> link_boxes_;
    std::vector<CostBox> waypoint_boxes_, merged_;
    std::vector<Pose> poses_;
};

template <class PosesOf>
PathOutcome PathQuery::run(const SensorOctree &tree, const LinkSet &links, size_t waypoints, PosesOf &&poses_of,
                           const PathSettings &settings, std::vector<CostBox> &boxes,
                           AmortizedEngine *amortized) {
    LinkSet &moving = posable_copy(links);
    CollisionSettings collision = settings.collision;
    collision.max_contacts = 0;  // yes/no per waypoint
    merged_.clear();
    PathOutcome out;
    for (size_t w = 0; w < waypoints; ++w) {
        poses_of(w, poses_);
        moving.set_poses(poses_);
        const CollisionOutcome hit = collide(amortized, tree, moving, collision);
        out.narrow_tests += hit.narrow_tests;
        if (hit.collided && out.first_collision < 0) out.first_collision = static_cast<int64_t>(w);
        if (collision.cost) {
            CostCollector &cost = amortized ? amortized->cost() : collider_.cost();
            link_boxes(moving, cost, link_boxes_);
            cost.finish(link_boxes_, UINT32_MAX, waypoint_boxes_, true);
            merge_cost(waypoint_boxes_);
        }
        if (settings.distance) {
            const DistanceOutcome d = distance(amortized, tree, moving, settings.distance_settings);
            out.narrow_tests += d.narrow_tests;
            if (d.found && d.distance < out.min_distance)
                out.min_distance = d.distance, out.min_distance_waypoint = static_cast<int64_t>(w);
        }
        if (out.first_collision >= 0 && !collision.cost && !settings.distance) break;
    }
    out.cost = finish_cost(collision.max_cost_boxes, boxes);
    return out;
}

}  // namespace octoprox
