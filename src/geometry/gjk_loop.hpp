// The GJK iteration itself, shared by the cell test (a convex piece against
// an axis-aligned box) and the pair test (two convex pieces): both walk the
// Minkowski difference A - B through the two support mappings they pass.
// Private to geometry/: include it from gjk.cpp only.
#pragma once

#include "geometry/gjk.hpp"

#include <cmath>

namespace octoprox::gjk_detail {

constexpr int kMaxIterations = 128;

inline void set_witnesses(const Simplex &simplex, GjkResult &result) {
    result.on_shape.setZero();
    result.on_cell.setZero();
    for (int i = 0; i < simplex.size; ++i) {
        result.on_shape += simplex.bary[i] * simplex.s[i];
        result.on_cell += simplex.bary[i] * simplex.c[i];
    }
}

inline bool already_in(const Simplex &simplex, const Vec3 &w) {
    for (int i = 0; i < simplex.size; ++i)
        if (simplex.w[i] == w) return true;
    return false;
}

// The stopping rules of a run: `zero` is the length below which the
// difference's closest point is rounding noise around the origin (the two
// touch or overlap); stop_above and stop_below as in GjkQuery.
struct GjkLimits {
    double zero = 0.0;
    double stop_above = 0.0;
    double stop_below = -1.0;
};

// support_a(d): A's point furthest along d; support_b(d): B's.  `direction`
// starts the search (any non-zero vector; the one between the shapes is best).
// The result's on_shape is on A, on_cell on B.
template <class SupportA, class SupportB>
GjkResult gjk_run(const SupportA &support_a, const SupportB &support_b, Vec3 direction, const GjkLimits &limits) {
    GjkResult result;
    Simplex simplex;
    if (direction.squaredNorm() == 0.0) direction = Vec3::UnitX();
    {
        const Vec3 s = support_a(direction);
        const Vec3 c = support_b(-direction);
        simplex.push(s - c, s, c);
        simplex.bary[0] = 1.0;
    }
    Vec3 v = simplex.w[0];
    const double zero = limits.zero;
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const double vv = v.squaredNorm();
        if (vv <= zero * zero) {
            v.setZero();
            break;
        }
        const Vec3 s = support_a(-v);
        const Vec3 c = support_b(v);
        const Vec3 w = s - c;
        const double vw = v.dot(w);
        // v.w / |v| is a lower bound of the distance (a separating plane).
        if (vw > 0.0 && vw * vw > limits.stop_above * limits.stop_above * vv) {
            result.distance = vw / std::sqrt(vv);
            set_witnesses(simplex, result);
            return result;
        }
        if (vv - vw <= kGjkRelativeTolerance * vv || already_in(simplex, w)) break;
        const Simplex previous = simplex;
        simplex.push(w, s, c);
        if (!simplex.reduce_to_closest()) {
            // A separating plane (v.w > 0) contradicts "origin inside": the
            // simplex has degenerated into a needle whose side tests are
            // rounding noise.  Keep the last good answer.
            if (vw > 0.0) {
                simplex = previous;
                break;
            }
            result.intersecting = true;
            result.simplex = simplex;
            return result;
        }
        const Vec3 next = simplex.closest();
        if (next.squaredNorm() >= vv) {  // no progress: the rounding floor is reached
            simplex = previous;
            break;
        }
        v = next;
        if (v.squaredNorm() <= zero * zero) {
            v.setZero();
            break;
        }
        if (limits.stop_below >= 0.0 && v.squaredNorm() <= limits.stop_below * limits.stop_below) break;
    }
    result.distance = v.norm();
    result.intersecting = result.distance == 0.0;
    if (result.intersecting) result.simplex = simplex;
    set_witnesses(simplex, result);
    return result;
}

}  // namespace octoprox::gjk_detail
