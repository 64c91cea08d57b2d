// The query context below the C ABI (an opx_query holds one): the engine
// chosen when it is made, the results of its last queries (contacts, cost
// boxes, per-link distances) and the cost pipeline.  Every query kind goes
// through it with the same engine verbs (engine.hpp), so a new kind is one
// more method here over the same engine.  One context per thread.
#pragma once

#include "query/amortized/amortized_engine.hpp"
#include "query/cell_description.hpp"
#include "query/cost_pipeline.hpp"
#include "query/path_query.hpp"
#include "query/self/self_collider.hpp"
#include "query/world/world_collider.hpp"

#include <memory>
#include <vector>

namespace octoprox {

enum class EngineKind { kDirect, kAmortized };

struct ContextOptions {
    EngineKind engine = EngineKind::kDirect;
    AmortizedOptions amortized;  // used by the amortized engine only
};

// A collision query's answer; its contacts and cost boxes stay in the context.
struct CollisionAnswer {
    CollisionOutcome outcome;
    CostSummary cost;  // with settings.cost
};

// A distance query's answer and what the nearest cell (or caller box) is;
// with per_link, every link's minimum stays in the context.
struct DistanceAnswer {
    DistanceOutcome outcome;
    CellSummary cell;  // when outcome.found
    // A world object's shape when it is the nearest (outcome.on_cell lies
    // on it; cell is then zeros); -1: a cell.
    int32_t object = -1;
    uint32_t object_shape = 0;
};

class QueryContext {
public:
    explicit QueryContext(const ContextOptions &options);

    EngineKind engine_kind() const { return kind_; }
    EngineStats stats() const { return engine_->stats(); }

    // Queries against an octree frame and the world's objects, when a
    // world is set (query/world/: the same for both engines); tree may
    // then be null.  World contacts follow the octree's, up to
    // max_contacts together.
    CollisionAnswer collide(const SensorOctree *tree, const LinkSet &links, const CollisionSettings &settings);
    DistanceAnswer distance(const SensorOctree *tree, const LinkSet &links, const DistanceSettings &settings,
                            bool per_link);
    CollisionAnswer collide(const SensorOctree &tree, const LinkSet &links, const CollisionSettings &settings) {
        return collide(&tree, links, settings);
    }
    DistanceAnswer distance(const SensorOctree &tree, const LinkSet &links, const DistanceSettings &settings,
                            bool per_link) {
        return distance(&tree, links, settings, per_link);
    }
    // The world collide() and distance() check besides the octree (null:
    // none); it must outlive its use and not change during a query.
    void set_world(const World *world) { world_ = world; }
    const World *world() const { return world_; }
    // `poses`: waypoint-major, one pose per link (path_query.hpp).  With a
    // world, each waypoint is also checked against its objects; tree may
    // then be null (no cost without it).
    PathOutcome path(const SensorOctree *tree, const LinkSet &links, const std::vector<Pose> &poses,
                     size_t waypoints, const PathSettings &settings);

    // A caller's boxes as the map (amortized engine only; an octree query
    // unbinds them).  These throw ApiError (invalid argument) otherwise;
    // require_box_engine checks the engine alone, before boxes are read.
    void require_box_engine() { amortized_engine(); }
    void bind_boxes(std::vector<Aabb> boxes);
    CollisionAnswer collide_boxes(const LinkSet &links, const CollisionSettings &settings);
    DistanceAnswer distance_boxes(const LinkSet &links, const DistanceSettings &settings, bool per_link);

    // The link set against itself at its current poses (query/self/): its
    // enabled pairs of links.  The contacts stay until the next self query.
    SelfCollisionOutcome self_collide(const LinkSet &links, const SelfCollisionSettings &settings) {
        return self_.collide(links, settings, self_contacts_);
    }
    SelfDistanceOutcome self_distance(const LinkSet &links, const SelfDistanceSettings &settings) {
        return self_.distance(links, settings);
    }
    const std::vector<SelfContact> &self_contacts() const { return self_contacts_; }

    // The map's obstacle grid for a threshold (SensorOctree::obstacle_grid),
    // kept while the map's identity and generation and the threshold stay:
    // a run of sphere queries asks the map once.  Null: no grid.
    const ObstacleGrid *obstacle_grid(const SensorOctree &tree, float threshold);

    // The results of the last queries.
    const std::vector<Contact> &contacts() const { return contacts_; }
    const std::vector<WorldContact> &world_contacts() const { return world_contacts_; }
    const std::vector<CostBox> &cost_boxes() const { return cost_boxes_; }
    const std::vector<double> &link_distances() const { return link_distances_; }
    // Of the octree of the last collision or path query (the cost boxes' cells).
    double resolution() const { return resolution_; }

private:
    AmortizedEngine &amortized_engine();
    AmortizedEngine &bound_boxes();
    // context_world.cpp: the world's part of an answer.
    void collide_world(const LinkSet &links, const CollisionSettings &settings, CollisionAnswer &answer);
    void distance_world(const LinkSet &links, const DistanceSettings &settings, bool per_link,
                        DistanceAnswer &answer);

    EngineKind kind_;
    std::unique_ptr<Engine> engine_;
    AmortizedEngine *amortized_ = nullptr;  // engine_, when it is the amortized engine
    CostPipeline cost_;
    PathQuery path_;
    std::vector<Contact> contacts_;
    std::vector<CostBox> cost_boxes_;
    std::vector<double> link_distances_;
    SelfCollider self_;
    std::vector<SelfContact> self_contacts_;
    double resolution_ = 0.0;
    const World *world_ = nullptr;
    WorldCollider world_collider_;
    std::vector<WorldContact> world_contacts_;
    struct GridKey {
        uint64_t identity = 0, generation = 0;
        float threshold = 0.0f;
    } grid_key_;
    std::shared_ptr<const ObstacleGrid> grid_;
    bool grid_known_ = false;  // grid_ is the one for grid_key_
};

}  // namespace octoprox
