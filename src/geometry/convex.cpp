#include "geometry/convex.hpp"

namespace octoprox {
namespace {

Vec3 cylinder_support(const Convex &c, const Vec3 &d) {
    const Vec3 local = c.axes.transpose() * d;
    const double radial = std::hypot(local.x(), local.y());
    Vec3 p(0.0, 0.0, sign_of(local.z()) * c.half.z());
    // Along the axis any point of the cap is a support point: take its centre.
    if (radial > 0.0) {
        p.x() = c.half.x() * local.x() / radial;
        p.y() = c.half.x() * local.y() / radial;
    }
    return c.center + c.axes * p;
}

Vec3 hull_support(const Convex &c, const Vec3 &d) {
    size_t best = 0;
    double best_dot = c.hull[0].dot(d);
    for (size_t i = 1; i < c.hull_count; ++i) {
        const double dot = c.hull[i].dot(d);
        if (dot > best_dot) best_dot = dot, best = i;
    }
    return c.hull[best];
}

Vec3 max_dot(const Vec3 *points, int n, const Vec3 &d) {
    int best = 0;
    for (int i = 1; i < n; ++i)
        if (points[i].dot(d) > points[best].dot(d)) best = i;
    return points[best];
}

}  // namespace

Vec3 Convex::support(const Vec3 &d) const {
    switch (kind) {
    case ConvexKind::kPoint: return center;
    case ConvexKind::kSegment: return max_dot(v, 2, d);
    case ConvexKind::kTriangle: return max_dot(v, 3, d);
    case ConvexKind::kBox: {
        const Vec3 local = axes.transpose() * d;
        return center + axes * box_support(Vec3::Zero(), half, local);
    }
    case ConvexKind::kCylinder: return cylinder_support(*this, d);
    case ConvexKind::kHull: return hull_support(*this, d);
    }
    return center;
}

}  // namespace octoprox
