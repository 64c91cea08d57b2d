// A batch query's worker: its own query context (engine and scratch) and
// its own posed copy of the robot, so workers on different threads share
// nothing but the read-only map, world and link set.  An opx_query keeps
// its workers (BatchWorkers) between calls: a warm batch allocates nothing
// per configuration, and the amortized engine's trees stay built.
//
// The octree may be null when a world is set: the objects alone are
// checked.  The world is only read by the workers: what it makes lazily
// for its first reader after a change (its tree of object shapes, its
// meshes' placed vertices) BatchWorkers::prepare makes on the caller's
// thread before the work is split.
#pragma once

#include "query/batch/batch_types.hpp"
#include "query/batch/posed_robot.hpp"
#include "query/batch/sphere_robot.hpp"
#include "query/context.hpp"

#include <memory>
#include <vector>

namespace octoprox {

class BatchWorker {
public:
    explicit BatchWorker(const ContextOptions &options) : context_(options) {}

    PosedRobot &robot() { return robot_; }
    // After robot().bind(): reads the posed copy's spheres, if it is made
    // of spheres alone.
    void bind_spheres() { spheres_.bind(robot_.links()); }
    QueryContext &context() { return context_; }

    // Row `row` of `rows` at its base pose: collided (world, and self with
    // settings.self_collision) and, with settings.distance, the minimum
    // distance.  Without distance it stops at the first contact.
    ConfigurationAnswer check(const SensorOctree *tree, const JointRows &rows, const BasePoses &bases, size_t row,
                              const ConfigurationSettings &settings);
    // The robot posed at `commanded` collides (world, and self when asked)?
    bool collides_at(const SensorOctree *tree, const double *commanded, const Pose &base,
                     const CollisionSettings &collision, bool self_collision);

private:
    // The map's obstacle grid when a check may place the robot's spheres
    // alone (a robot of spheres, the octree only, yes or no without cost
    // or unknown space as obstacle), else null.
    const ObstacleGrid *sphere_grid(const SensorOctree *tree, const CollisionSettings &collision,
                                    bool self_collision);
    bool spheres_collide(const SensorOctree &tree, const ObstacleGrid *grid, const double *commanded,
                         const Pose &base, const CollisionSettings &collision);
    bool collides(const SensorOctree *tree, const LinkSet &posed, const CollisionSettings &collision,
                  bool self_collision);
    ConfigurationAnswer with_distance(const SensorOctree *tree, const LinkSet &posed,
                                      const ConfigurationSettings &settings);
    void add_self_distance(const LinkSet &posed, const ConfigurationSettings &settings, ConfigurationAnswer &answer);

    QueryContext context_;
    PosedRobot robot_;
    SphereRobot spheres_;
    std::vector<double> row_;  // one configuration copied from the caller
};

// The workers of one opx_query, made on first use and kept.
class BatchWorkers {
public:
    explicit BatchWorkers(const ContextOptions &options) : options_(options) {}

    // `count` workers ready to pose `links` with `joints` and to check the
    // world's objects (null: none) beside the octree.  The world's object
    // tree and mesh placements are made here, so the workers only read.
    void prepare(size_t count, const LinkSet &links, const JointTree &joints, const World *world);
    BatchWorker &operator[](size_t index) { return *workers_[index]; }

private:
    ContextOptions options_;
    std::vector<std::unique_ptr<BatchWorker>> workers_;
};

}  // namespace octoprox
