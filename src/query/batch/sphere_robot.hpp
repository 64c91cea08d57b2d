// A robot made of spheres alone (the model of sphere-based planners),
// checked configuration after configuration from the link poses forward
// kinematics gives: each sphere's centre is placed as the link set would
// place it and asked of the map's obstacle grid (sphere_query.hpp), with
// no shapes, boxes or tree of shapes to update.  The answer is the one
// the engines give for the placed link set: a link set of spheres
// collides when one of its spheres does, and each sphere's answer is the
// descent's, bit for bit.
#pragma once

#include "geometry/pose.hpp"
#include "query/spheres/sphere_query.hpp"
#include "robot/linkset.hpp"

#include <vector>

namespace octoprox {

class SphereRobot {
public:
    // Reads the spheres of `links` (their centres in their link's frame,
    // their radius with padding); false, and nothing bound, when any of
    // its shapes (attached objects' included) is not a sphere.
    bool bind(const LinkSet &links);
    bool bound() const { return bound_; }

    // Whether a sphere of the enabled links, at `link_poses` (one per
    // link, map frame), touches an obstacle.  `grid` is the map's grid for
    // settings.threshold_log_odds (null: each sphere takes the descent).
    bool collides(const SensorOctree &tree, const ObstacleGrid *grid, const std::vector<Pose> &link_poses,
                  const SphereSettings &settings) const;

private:
    struct Sphere {
        Vec3 local;     // centre in the link frame
        double radius;  // padding included
    };
    // A link's spheres and a sphere holding them all (link frame): a link
    // whose bounding sphere is far from every obstacle is done at once.
    struct LinkSpheres {
        uint32_t link;
        uint32_t first, count;  // in spheres_
        Vec3 center;
        double radius;
    };
    void bound_link(LinkSpheres &group) const;

    std::vector<Sphere> spheres_;     // the enabled links' alone, link after link
    std::vector<LinkSpheres> links_;
    bool bound_ = false;
};

}  // namespace octoprox
