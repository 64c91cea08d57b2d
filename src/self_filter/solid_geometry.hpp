// The robot's convex solids for self-filtering: a convex core (a point,
// segment, triangle, box, cylinder or hull, geometry/convex.hpp) grown by
// a ball of `radius`.  Exact nearest points for every kind (a hull's by
// GJK, exact between polytopes), and the first point at which a ray
// enters a grown core.
#pragma once

#include "geometry/convex.hpp"

namespace octoprox {

// A ray that comes this close to a solid counts as entering it (metres).
constexpr double kEntryTouch = 1e-9;

// The point of `core` nearest `x`; `x` itself when the core holds it.
Vec3 nearest_on_core(const Convex &core, const Vec3 &x);

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
