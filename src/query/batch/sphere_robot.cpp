#include "query/batch/sphere_robot.hpp"

#include "query/spheres/sphere_grid.hpp"

#include <algorithm>

namespace octoprox {
namespace {

// Added to a link's bounding radius: far more than the rounding of
// placing its centre and the spheres' (1e-15 of the coordinates), and
// than the grid's margin (1e-8 of a cell), so that a link found clear
// holds only spheres each found clear, and far less than matters.
constexpr double kBoundSlack = 1e-6;  // m

}  // namespace

// The centre and radius are the ones place_shape gives a sphere: the
// link pose applied to the shape's local translation, and the placed
// shape's inflation (padding plus radius, summed where it was placed).
// A link's shapes (its own, then its attached objects') are consecutive.
bool SphereRobot::bind(const LinkSet &links) {
    spheres_.clear();
    links_.clear();
    bound_ = false;
    for (const PlacedShape &placed : links.placed())
        if (placed.kind != ShapeKind::kSphere) return false;
    for (const PlacedShape &placed : links.placed()) {
        if (!links.link(placed.link).enabled) continue;
        if (links_.empty() || links_.back().link != placed.link)
            links_.push_back(LinkSpheres{placed.link, static_cast<uint32_t>(spheres_.size()), 0, Vec3::Zero(), 0.0});
        spheres_.push_back(Sphere{placed.def->local.translation, placed.inflation});
        ++links_.back().count;
    }
    for (LinkSpheres &group : links_) bound_link(group);
    bound_ = true;
    return true;
}

// The mean of the link's sphere centres, and the radius reaching the
// farthest sphere's far side.
void SphereRobot::bound_link(LinkSpheres &group) const {
    Vec3 sum = Vec3::Zero();
    for (uint32_t i = group.first; i < group.first + group.count; ++i) sum += spheres_[i].local;
    group.center = sum / double(group.count);
    double radius = 0.0;
    for (uint32_t i = group.first; i < group.first + group.count; ++i)
        radius = std::max(radius, (spheres_[i].local - group.center).norm() + spheres_[i].radius);
    group.radius = radius + kBoundSlack;
}

bool SphereRobot::collides(const SensorOctree &tree, const ObstacleGrid *grid, const std::vector<Pose> &link_poses,
                           const SphereSettings &settings) const {
    // A grid's clearances count its own threshold's obstacles: read for a
    // lower threshold they would call colliding spheres clear.  As
    // sphere_collides, use it only for the threshold it was built for.
    if (grid != nullptr && (settings.unknown_occupied || grid->threshold() != settings.threshold_log_odds))
        grid = nullptr;
    for (const LinkSpheres &group : links_) {
        const Pose &pose = link_poses[group.link];
        if (grid != nullptr && group.count > 1 && sphere_surely_clear(*grid, pose.apply(group.center), group.radius))
            continue;
        for (uint32_t i = group.first; i < group.first + group.count; ++i) {
            const Vec3 center = pose.apply(spheres_[i].local);
            if (grid != nullptr && sphere_surely_clear(*grid, center, spheres_[i].radius)) continue;
            if (sphere_collides(tree, grid, center, spheres_[i].radius, settings)) return true;
        }
    }
    return false;
}

}  // namespace octoprox
