// The direct engine's collision query (paper IV.B, Algorithm 1): the
// octree, as it is, against the BVH of the robot's placed shapes; no
// per-frame preprocessing of the map.
#pragma once

#include "octree/octree_cell.hpp"
#include "octree/sensor_octree.hpp"
#include "query/collision_types.hpp"
#include "query/contact_sink.hpp"
#include "query/cost_collector.hpp"
#include "robot/linkset.hpp"

namespace octoprox {

class DirectCollider {
public:
    // Runs one query; contacts is cleared and filled (its capacity is kept,
    // so warm queries allocate nothing).
    CollisionOutcome collide(const SensorOctree &tree, const LinkSet &links,
                             const CollisionSettings &settings, std::vector<Contact> &contacts);
    // With settings.cost: the (link, cell) pairs of the last query.
    CostCollector &cost() { return cost_; }

private:
    using Cell = OctreeCell;

    void enter_at_cubes(const OctreeView &view);
    void recurse(const Cell &cell, int32_t robot_node);
    void descend_octree(const Cell &cell, int32_t robot_node);
    void test_leaf_pair(const Cell &cell, int32_t robot_node);
    bool skip_child(const Cell &child) const;
    void test_obstacle(const Cell &cell, const PlacedShape &shape);
    void test_cost(const Cell &cell, const PlacedShape &shape);
    // Where a cell's obstacles can lie (octree_cell.hpp obstacle_bounds).
    Aabb bounding_box(const Cell &cell) const { return obstacle_bounds(*view_, cell, model_); }

    const OctreeView *view_ = nullptr;
    const SensorOctree *tree_ = nullptr;
    const LinkSet *links_ = nullptr;
    CollisionSettings settings_;
    ContactSink *contacts_ = nullptr;  // the query's, while it runs
    CollisionOutcome outcome_;
    CostCollector cost_;
    bool done_ = false;
    // The map's inner obstacle boxes hold for this query when obstacles are
    // leaves at or above its threshold and cost (which also looks for
    // uncertain and unknown cells) is off.
    ObstacleModel model_;
};

}  // namespace octoprox
