#include "self_filter/solid_geometry.hpp"

#include "geometry/gjk.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

// Steps before a ray that keeps creeping towards a solid it only grazes
// is taken as touching it.  Newton halves the gap to a double root each
// step, so 200 covers any gap down to far below kEntryTouch.
constexpr int kMaxNewtonSteps = 200;

Vec3 nearest_on_segment(const Vec3 &a, const Vec3 &b, const Vec3 &x) {
    const Vec3 ab = b - a;
    const double length2 = ab.squaredNorm();
    if (length2 == 0.0) return a;
    const double t = std::clamp((x - a).dot(ab) / length2, 0.0, 1.0);
    return a + t * ab;
}

// The nearest point of triangle abc by the region of the plane x projects
// into: a vertex, an edge or the face.
Vec3 nearest_on_triangle(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &x) {
    const Vec3 ab = b - a, ac = c - a, ax = x - a;
    const double d1 = ab.dot(ax), d2 = ac.dot(ax);
    if (d1 <= 0.0 && d2 <= 0.0) return a;
    const Vec3 bx = x - b;
    const double d3 = ab.dot(bx), d4 = ac.dot(bx);
    if (d3 >= 0.0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
    const Vec3 cx = x - c;
    const double d5 = ab.dot(cx), d6 = ac.dot(cx);
    if (d6 >= 0.0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double sum = va + vb + vc;
    if (!(sum > 0.0)) return nearest_on_segment(a, b, x);  // a degenerate triangle
    return a + (vb / sum) * ab + (vc / sum) * ac;
}

Vec3 nearest_on_box(const Convex &box, const Vec3 &x) {
    const Vec3 local = box.axes.transpose() * (x - box.center);
    const Vec3 clamped = local.cwiseMax(-box.half).cwiseMin(box.half);
    if (clamped == local) return x;
    return box.center + box.axes * clamped;
}

Vec3 nearest_on_cylinder(const Convex &cylinder, const Vec3 &x) {
    const Vec3 local = cylinder.axes.transpose() * (x - cylinder.center);
    const double radius = cylinder.half.x(), half_length = cylinder.half.z();
    const double radial = std::hypot(local.x(), local.y());
    const double z = std::clamp(local.z(), -half_length, half_length);
    if (radial <= radius && z == local.z()) return x;
    const double scale = radial > radius ? radius / radial : 1.0;
    return cylinder.center + cylinder.axes * Vec3(local.x() * scale, local.y() * scale, z);
}

Vec3 nearest_on_hull(const Convex &hull, const Vec3 &x) {
    Convex point;
    point.kind = ConvexKind::kPoint;
    point.center = x;
    GjkPairQuery query;
    query.a = &point, query.b = &hull;
    const GjkResult result = gjk_pair_distance(query);
    return result.intersecting ? x : result.on_cell;
}

}  // namespace

Vec3 nearest_on_core(const Convex &core, const Vec3 &x) {
    switch (core.kind) {
    case ConvexKind::kPoint: return core.center;
    case ConvexKind::kSegment: return nearest_on_segment(core.v[0], core.v[1], x);
    case ConvexKind::kTriangle: return nearest_on_triangle(core.v[0], core.v[1], core.v[2], x);
    case ConvexKind::kBox: return nearest_on_box(core, x);
    case ConvexKind::kCylinder: return nearest_on_cylinder(core, x);
    case ConvexKind::kHull: return nearest_on_hull(core, x);
    }
    return core.center;
}

double grown_core_entry(const Convex &core, double radius, const Vec3 &origin, const Vec3 &dir, double t_max) {
    double t = 0.0;
    for (int step = 0; step < kMaxNewtonSteps; ++step) {
        const Vec3 x = origin + t * dir;
        const Vec3 away = x - nearest_on_core(core, x);
        const double distance = away.norm();
        const double gap = distance - radius;
        if (gap <= kEntryTouch) return t;
        const double slope = dir.dot(away) / distance;  // d(distance)/dt, distance > radius >= 0
        if (!(slope < 0.0)) return -1.0;  // moving away: convexity leaves no entry ahead
        const double next = t - gap / slope;
        if (!(next <= t_max)) return -1.0;
        if (next == t) return t;  // no step left in double: the gap is rounding
        t = next;
    }
    return t;
}

}  // namespace octoprox
