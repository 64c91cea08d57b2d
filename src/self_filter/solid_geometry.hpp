// The robot's convex solids for self-filtering: a convex core (a point,
// segment, triangle, box, cylinder or hull, geometry/convex.hpp) grown by
// a ball of `radius`.  Exact nearest points for every kind (a hull's by
// GJK, exact between polytopes), and the first point at which a ray
// enters a grown core.
#pragma once

#include "geometry/aabb.hpp"
#include "geometry/convex.hpp"

#include <utility>

namespace octoprox {

// A ray that comes this close to a solid counts as entering it (metres).
constexpr double kEntryTouch = 1e-9;

// The point of `core` nearest `x`; `x` itself when the core holds it.
Vec3 nearest_on_core(const Convex &core, const Vec3 &x);

// Narrows [t0, t1] to the part of origin + t * dir inside the closed box;
// false when that part is empty.
inline bool segment_in_box(const Aabb &box, const Vec3 &origin, const Vec3 &dir, double &t0, double &t1) {
    for (int axis = 0; axis < 3; ++axis) {
        if (dir[axis] == 0.0) {
            if (origin[axis] < box.lo[axis] || origin[axis] > box.hi[axis]) return false;
            continue;
        }
        const double inv = 1.0 / dir[axis];
        double a = (box.lo[axis] - origin[axis]) * inv, b = (box.hi[axis] - origin[axis]) * inv;
        if (a > b) std::swap(a, b);
        t0 = a > t0 ? a : t0, t1 = b < t1 ? b : t1;
        if (t0 > t1) return false;
    }
    return true;
}

// A ray's slab test against many boxes: its reciprocal direction once.
class RaySlabs {
public:
    RaySlabs(const Vec3 &origin, const Vec3 &dir) : origin_(origin), dir_(dir) {
        for (int axis = 0; axis < 3; ++axis) inverse_[axis] = dir[axis] != 0.0 ? 1.0 / dir[axis] : 0.0;
    }
    // Whether the segment t in [0, t_max] meets `box` grown by `margin`;
    // t0: where it enters.  As segment_in_box.
    bool enters(const Aabb &box, double margin, double t_max, double &t0) const {
        double t1 = t_max;
        t0 = 0.0;
        for (int axis = 0; axis < 3; ++axis) {
            const double lo = box.lo[axis] - margin - origin_[axis], hi = box.hi[axis] + margin - origin_[axis];
            if (dir_[axis] == 0.0) {
                if (lo > 0.0 || hi < 0.0) return false;
                continue;
            }
            double a = lo * inverse_[axis], b = hi * inverse_[axis];
            if (a > b) std::swap(a, b);
            t0 = a > t0 ? a : t0, t1 = b < t1 ? b : t1;
        }
        return t0 <= t1;
    }

private:
    Vec3 origin_, dir_, inverse_;
};

// Whether the core grown by `radius` holds `x` (its distance to the core
// is at most `radius`).
inline bool grown_core_holds(const Convex &core, double radius, const Vec3 &x) {
    return (x - nearest_on_core(core, x)).squaredNorm() <= radius * radius;
}

// The first t in [0, t_max] at which origin + t * dir lies within `radius`
// + kEntryTouch of the core, or -1 when there is none.  No point of the ray
// before the returned t lies within `radius` of the core.  The origin
// should lie outside the grown core (else 0 is returned).
//
// Newton's method on the distance along the ray, which is convex in t:
// from the left, each step lands at or before the first root, so the
// iteration never passes the entry, and a step that would go past t_max,
// or a distance that stops falling, proves there is none.
double grown_core_entry(const Convex &core, double radius, const Vec3 &origin, const Vec3 &dir, double t_max);

}  // namespace octoprox
