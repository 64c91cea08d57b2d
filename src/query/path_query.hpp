// Path queries: a sequence of waypoints, each a pose per link, checked in
// order with one engine (the amortized engine's trees stay bound across the
// waypoints and paths), with the cost of the uncertain and unknown space
// the motion sweeps through, from samples of the path (paper IV.C).  With
// a world, each waypoint is also checked against its objects
// (query/world/), which have no cost: they are known.
#pragma once

#include "query/cost_pipeline.hpp"
#include "query/engine.hpp"
#include "query/world/world_collider.hpp"

#include <limits>
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

// What a path query checks: `poses` holds waypoint w's link poses (one per
// link of `links`) at [w * link_count, (w + 1) * link_count).  The octree,
// the world, or both (neither null together; no cost without an octree).
struct PathRequest {
    const SensorOctree *tree;
    const World *world;
    const LinkSet &links;
    const std::vector<Pose> &poses;
    size_t waypoints;
    const PathSettings &settings;
};

class PathQuery {
public:
    // Checks the path with `engine`; `cost` gathers the cost of the
    // waypoints and writes the path's cost boxes to `boxes`.
    PathOutcome run(const PathRequest &request, Engine &engine, CostPipeline &cost, std::vector<CostBox> &boxes);

private:
    LinkSet &posable_copy(const LinkSet &links);
    // Puts `moving` (the private copy) at waypoint w's poses.
    void pose_waypoint(LinkSet &moving, const PathRequest &request, size_t w);
    // Waypoint w collides (octree or objects)?
    bool collides(const PathRequest &request, Engine &engine, const LinkSet &moving, const CollisionSettings &collision,
                  PathOutcome &out);
    // Waypoint w's distance (the octree's and the objects' least), into out.
    void measure(const PathRequest &request, Engine &engine, const LinkSet &moving, size_t w, PathOutcome &out);

    std::unique_ptr<LinkSet> copy_;
    uint64_t copy_source_ = 0;  // identity of the set copied
    std::vector<Contact> contacts_;  // none kept: a waypoint's answer is yes or no
    std::vector<Pose> poses_;
    WorldCollider world_;
};

}  // namespace octoprox
