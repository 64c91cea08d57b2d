#include "query/spheres/trajectory_cost.hpp"

namespace octoprox {

// The centres are placed as SphereRobot places them (the link pose applied
// to the shape's local translation).
bool TrajectorySpheres::bind(const LinkSet &links, const JointTree &joints) {
    spheres_.clear();
    for (const PlacedShape &placed : links.placed())
        if (placed.kind != ShapeKind::kSphere) return false;
    for (const PlacedShape &placed : links.placed())
        if (links.link(placed.link).enabled)
            spheres_.push_back(Sphere{placed.link, placed.def->local.translation, placed.inflation});
    // Each link's joint toward its parent, then the chains.
    std::vector<uint32_t> parent_joint(joints.link_count(), kNoIndex);
    for (uint32_t j = 0; j < joints.joint_count(); ++j) parent_joint[joints.joint(j).child_link] = j;
    chains_.assign(joints.link_count(), {});
    for (uint32_t link = 0; link < joints.link_count(); ++link)
        for (uint32_t at = link; parent_joint[at] != kNoIndex; at = joints.joint(parent_joint[at]).parent_link)
            if (joints.joint(parent_joint[at]).moves()) chains_[link].push_back(parent_joint[at]);
    return true;
}

double TrajectorySpheres::waypoint(const SensorOctree *tree, const ObstacleGrid *grid, const WorldIndex *world,
                                   const JointTree &joints, const double *commanded, const Pose &base,
                                   const SphereDistanceSettings &settings, double *gradient,
                                   Scratch &scratch) const {
    scratch.positions.resize(joints.joint_count());
    scratch.poses.resize(joints.link_count());
    joints.positions_from(commanded, scratch.positions.data());
    joints.link_poses(base, scratch.positions.data(), scratch.poses.data());
    const double eps = settings.max_distance;
    double cost = 0.0;
    for (const Sphere &sphere : spheres_) {
        const Vec3 center = scratch.poses[sphere.link].apply(sphere.local);
        const SphereDistance d = sphere_distance(tree, grid, world, center, sphere.radius, settings, scratch.distance);
        double slope = 0.0;
        cost += chomp_penalty(d.distance, eps, slope);
        if (slope == 0.0) continue;
        const Vec3 pull = slope * d.gradient;  // d cost / d centre
        for (uint32_t j : chains_[sphere.link]) {
            const Joint &joint = joints.joint(j);
            const Pose &frame = scratch.poses[joint.child_link];
            const Vec3 axis = frame.rotation * joint.axis;
            const Vec3 motion = joint.type == JointType::kPrismatic ? axis : axis.cross(center - frame.translation);
            const uint32_t master = joints.master(j);
            if (master != kNoIndex && joints.joint(master).moves())
                gradient[master] += joints.multiplier(j) * pull.dot(motion);
        }
    }
    return cost;
}

}  // namespace octoprox
