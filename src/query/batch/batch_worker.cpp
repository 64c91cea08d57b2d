#include "query/batch/batch_worker.hpp"

#include <algorithm>

namespace octoprox {
namespace {

// Above this the distance query alone settles "no contact": collision
// tests decide touching at 1e-9 m, and exact distances err by far less
// than a micrometre (docs/geometry.md), so the collision test would agree.
constexpr double kSurelyApart = 1e-6;

}  // namespace

ConfigurationAnswer BatchWorker::check(const SensorOctree *tree, const JointRows &rows, const BasePoses &bases,
                                       size_t row, const ConfigurationSettings &settings) {
    row_.resize(rows.model_count());
    rows.read(row, row_.data());
    if (!settings.distance)
        if (const ObstacleGrid *grid = sphere_grid(tree, settings.collision, settings.self_collision)) {
            ConfigurationAnswer answer;
            answer.collided = spheres_collide(*tree, grid, row_.data(), bases.at(row), settings.collision);
            return answer;
        }
    const LinkSet &posed = robot_.pose(row_.data(), bases.at(row));
    if (settings.distance) return with_distance(tree, posed, settings);
    ConfigurationAnswer answer;
    answer.collided = collides(tree, posed, settings.collision, settings.self_collision);
    return answer;
}

bool BatchWorker::collides_at(const SensorOctree *tree, const double *commanded, const Pose &base,
                              const CollisionSettings &collision, bool self_collision) {
    if (const ObstacleGrid *grid = sphere_grid(tree, collision, self_collision))
        return spheres_collide(*tree, grid, commanded, base, collision);
    return collides(tree, robot_.pose(commanded, base), collision, self_collision);
}

const ObstacleGrid *BatchWorker::sphere_grid(const SensorOctree *tree, const CollisionSettings &collision,
                                             bool self_collision) {
    if (!spheres_.bound() || tree == nullptr || context_.world() != nullptr || self_collision || collision.cost ||
        collision.unknown_occupied)
        return nullptr;
    return context_.obstacle_grid(*tree, collision.threshold_log_odds);
}

bool BatchWorker::spheres_collide(const SensorOctree &tree, const ObstacleGrid *grid, const double *commanded,
                                  const Pose &base, const CollisionSettings &collision) {
    SphereSettings settings;
    settings.threshold_log_odds = collision.threshold_log_odds;
    settings.point_extents = collision.point_extents;
    return spheres_.collides(tree, grid, robot_.pose_links(commanded, base), settings);
}

bool BatchWorker::collides(const SensorOctree *tree, const LinkSet &posed, const CollisionSettings &collision,
                           bool self_collision) {
    if (context_.collide(tree, posed, collision).outcome.collided) return true;
    if (!self_collision) return false;
    SelfCollisionSettings yes_no;
    yes_no.max_contacts = 0;
    return context_.self_collide(posed, yes_no).collided;
}

// The distance first; the collision test only when the distance leaves
// touching open.  With self-collision, the same for the self distance, the
// answer being the nearer of the two.
ConfigurationAnswer BatchWorker::with_distance(const SensorOctree *tree, const LinkSet &posed,
                                               const ConfigurationSettings &settings) {
    const DistanceAnswer nearest = context_.distance(tree, posed, settings.distance_settings, false);
    ConfigurationAnswer answer;
    answer.distance = nearest.outcome.found ? nearest.outcome.distance : settings.distance_settings.cutoff;
    const bool may_touch = nearest.outcome.found && nearest.outcome.distance <= kSurelyApart;
    answer.collided = may_touch && collides(tree, posed, settings.collision, false);
    if (settings.self_collision) add_self_distance(posed, settings, answer);
    return answer;
}

void BatchWorker::add_self_distance(const LinkSet &posed, const ConfigurationSettings &settings,
                                    ConfigurationAnswer &answer) {
    SelfDistanceSettings self;
    self.cutoff = settings.distance_settings.cutoff;
    const SelfDistanceOutcome nearest = context_.self_distance(posed, self);
    if (nearest.found) answer.distance = std::min(answer.distance, nearest.distance);
    if (answer.collided || !nearest.found || nearest.distance > kSurelyApart) return;
    SelfCollisionSettings yes_no;
    yes_no.max_contacts = 0;
    answer.collided = context_.self_collide(posed, yes_no).collided;
}

// The world's lazily made parts (its object tree, its meshes' placed
// vertices) are made here, on the caller's thread: the workers only read.
void BatchWorkers::prepare(size_t count, const LinkSet &links, const JointTree &joints, const World *world) {
    if (world != nullptr)
        for (const PlacedShape *shape : world->index().shapes)
            if (shape->kind == ShapeKind::kMesh) shape->place_mesh();
    while (workers_.size() < count) workers_.push_back(std::make_unique<BatchWorker>(options_));
    for (size_t i = 0; i < count; ++i) {
        workers_[i]->robot().bind(links, joints);
        workers_[i]->bind_spheres();
        workers_[i]->context().set_world(world);
    }
}

}  // namespace octoprox
