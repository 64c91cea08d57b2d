// Rays of a sensor frame cut short before they reach their points: the
// insert asks a RayClip about each point, and a cut ray frees the cells
// before its cut point as a ray cut at max_range does.  The robot's own
// body (self_filter/) is the clip the library has.
#pragma once

#include "geometry/pose.hpp"

namespace octoprox {

struct RayCut {
    enum Kind { kKeep, kOnRobot, kShadowed };
    Kind kind = kKeep;
    double t = 1.0;  // the cut point is origin + t * (end - origin), 0 <= t <= 1
};

class RayClip {
public:
    virtual ~RayClip() = default;
    // The ray from the clip's origin (the sensor's, fixed when the clip was
    // made) to `end`, map frame.  `end_is_point`: `end` is a sensed point
    // (it may be a robot point); false for a ray already cut at max_range,
    // which can only be shadowed.  Called from several threads at once.
    virtual RayCut cut(const Vec3 &end, bool end_is_point) const = 0;
};

}  // namespace octoprox
