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
#include "query/context.hpp"

#include <memory>
#include <vector>

namespace octoprox {

class BatchWorker {
public:
    explicit BatchWorker(const ContextOptions &options) : context_(options) {}

    PosedRobot &robot() { return robot_; }
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
    bool collides(const SensorOctree *tree, const LinkSet &posed, const CollisionSettings &collision,
                  bool self_collision);
    ConfigurationAnswer with_distance(const SensorOctree *tree, const LinkSet &posed,
                                      const ConfigurationSettings &settings);
    void add_self_distance(const LinkSet &posed, const ConfigurationSettings &settings, ConfigurationAnswer &answer);

    QueryContext context_;
    PosedRobot robot_;
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
