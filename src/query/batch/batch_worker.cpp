#include "query/batch/batch_worker.hpp"

#include "base/error.hpp"

namespace octoprox {
namespace {

// Above this the distance query alone settles "no contact": collision
// tests decide touching at 1e-9 m, and exact distances err by far less
// than a micrometre (docs/geometry.md), so the collision test would agree.
constexpr double kSurelyApart = 1e-6;

}  // namespace

ConfigurationAnswer BatchWorker::check(const SensorOctree &tree, const JointRows &rows, const BasePoses &bases,
                                       size_t row, const ConfigurationSettings &settings) {
    row_.resize(rows.joint_count);
    rows.read(row, row_.data());
    const LinkSet &posed = robot_.pose(row_.data(), bases.at(row));
    if (settings.distance) return with_distance(tree, posed, settings);
    ConfigurationAnswer answer;
    answer.collided = collides(tree, posed, settings.collision, settings.self_collision);
    return answer;
}

bool BatchWorker::collides_at(const SensorOctree &tree, const double *commanded, const Pose &base,
                              const CollisionSettings &collision, bool self_collision) {
    return collides(tree, robot_.pose(commanded, base), collision, self_collision);
}

bool BatchWorker::collides(const SensorOctree &tree, const LinkSet &posed, const CollisionSettings &collision,
                           bool self_collision) {
    const CollisionAnswer world = context_.collide(tree, posed, collision);
    narrow_tests_ += world.outcome.narrow_tests;
    if (world.outcome.collided) return true;
    if (self_collision) throw ApiError(OPX_ERROR_UNSUPPORTED, "self_collision is not available yet");
    return false;
}

// The distance first; the collision test only when the distance leaves
// touching open.
ConfigurationAnswer BatchWorker::with_distance(const SensorOctree &tree, const LinkSet &posed,
                                               const ConfigurationSettings &settings) {
    const DistanceAnswer nearest = context_.distance(tree, posed, settings.distance_settings, false);
    narrow_tests_ += nearest.outcome.narrow_tests;
    ConfigurationAnswer answer;
    answer.distance = nearest.outcome.found ? nearest.outcome.distance : settings.distance_settings.cutoff;
    const bool may_touch = nearest.outcome.found && nearest.outcome.distance <= kSurelyApart;
    answer.collided = may_touch && collides(tree, posed, settings.collision, false);
    if (settings.self_collision) throw ApiError(OPX_ERROR_UNSUPPORTED, "self_collision is not available yet");
    return answer;
}

void BatchWorkers::prepare(size_t count, const LinkSet &links, const JointTree &joints) {
    while (workers_.size() < count) workers_.push_back(std::make_unique<BatchWorker>(options_));
    for (size_t i = 0; i < count; ++i) workers_[i]->robot().bind(links, joints);
}

}  // namespace octoprox
