// Convex shapes as support mappings, in the map frame.  Every narrow-phase
// test in the library is "cell box vs convex piece": the piece is one of
// these, and GJK (gjk.hpp) works on any pair of them.
#pragma once

#include "geometry/pose.hpp"

#include <cmath>
#include <cstddef>

namespace octoprox {

enum class ConvexKind : int { kPoint, kSegment, kTriangle, kBox, kCylinder, kHull };

// A convex piece placed in the map frame, without its padding (padding is a
// ball added to the distance: Minkowski sums are exact that way).
struct Convex {
    ConvexKind kind = ConvexKind::kPoint;
    Vec3 center = Vec3::Zero();   // point, box and cylinder centre
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // box/cylinder frame (columns)
    Vec3 half = Vec3::Zero();     // box: half extents; cylinder: (radius, radius, half length)
    Vec3 v[3];                    // segment (v[0], v[1]) and triangle corners
    const Vec3 *hull = nullptr;   // hull vertices (owned elsewhere)
    size_t hull_count = 0;

    Vec3 support(const Vec3 &d) const;
};

inline double sign_of(double x) { return x >= 0.0 ? 1.0 : -1.0; }

// A support point of the axis-aligned box (center, half) in direction d.
inline Vec3 box_support(const Vec3 &center, const Vec3 &half, const Vec3 &d) {
    return Vec3(center.x() + sign_of(d.x()) * half.x(), center.y() + sign_of(d.y()) * half.y(),
                center.z() + sign_of(d.z()) * half.z());
}

}  // namespace octoprox
