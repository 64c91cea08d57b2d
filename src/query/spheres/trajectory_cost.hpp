// The obstacle cost of a trajectory of a robot made of spheres, and its
// gradient with respect to every joint at every waypoint (spheres.h states
// the penalty).  Each waypoint: forward kinematics places the spheres,
// sphere_distance.hpp gives each its signed distance d and unit gradient,
// and the penalty's slope times that gradient goes back to the joints
// through the link Jacobians: a revolute joint moves a centre c by
// axis x (c - joint origin), a prismatic one by its axis, and a mimic
// joint's share goes to its master times its multiplier.
#pragma once

#include "query/spheres/sphere_distance.hpp"
#include "robot/joint_tree.hpp"
#include "robot/linkset.hpp"

#include <vector>

namespace octoprox {

// CHOMP's penalty of a signed distance d for an activation distance eps:
// -d + eps / 2 inside, (d - eps)^2 / (2 eps) up to eps, 0 beyond; and its
// slope (continuous: -1, then (d - eps) / eps, then 0).
inline double chomp_penalty(double d, double eps, double &slope) {
    if (d < 0.0) {
        slope = -1.0;
        return -d + 0.5 * eps;
    }
    if (d < eps) {
        slope = (d - eps) / eps;
        return 0.5 * (d - eps) * (d - eps) / eps;
    }
    slope = 0.0;
    return 0.0;
}

class TrajectorySpheres {
public:
    // The enabled links' spheres (centre in the link frame, radius with
    // padding) and each link's chain of moving joints; false when a shape
    // is not a sphere.
    bool bind(const LinkSet &links, const JointTree &joints);

    struct Scratch {
        std::vector<double> positions;
        std::vector<Pose> poses;
        SphereDistanceScratch distance;
    };

    // One waypoint: `commanded` holds the model's joint values; returns
    // its cost and adds its gradient (model order) into `gradient`.
    double waypoint(const SensorOctree *tree, const ObstacleGrid *grid, const WorldIndex *world,
                    const JointTree &joints, const double *commanded, const Pose &base,
                    const SphereDistanceSettings &settings, double *gradient, Scratch &scratch) const;

private:
    struct Sphere {
        uint32_t link;
        Vec3 local;
        double radius;
    };
    std::vector<Sphere> spheres_;
    std::vector<std::vector<uint32_t>> chains_;  // per link: its moving joints up to the root
};

}  // namespace octoprox
