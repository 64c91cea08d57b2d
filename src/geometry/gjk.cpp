#include "geometry/gjk.hpp"

#include "geometry/simplex.hpp"

#include <cmath>

namespace octoprox {
namespace {

constexpr int kMaxIterations = 128;

void set_witnesses(const Simplex &simplex, GjkResult &result) {
    result.on_shape.setZero();
    result.on_cell.setZero();
    for (int i = 0; i < simplex.size; ++i) {
        result.on_shape += simplex.bary[i] * simplex.s[i];
        result.on_cell += simplex.bary[i] * simplex.c[i];
    }
}

bool already_in(const Simplex &simplex, const Vec3 &w) {
    for (int i = 0; i < simplex.size; ++i)
        if (simplex.w[i] == w) return true;
    return false;
}

}  // namespace

GjkResult gjk_cell_distance(const GjkQuery &q) {
    GjkResult result;
    Simplex simplex;
    // Start from the direction between the centres: usually close to the answer.
    Vec3 direction = q.cell_center - q.shape->support(Vec3::UnitX());
    if (direction.squaredNorm() == 0.0) direction = Vec3::UnitX();
    {
        const Vec3 s = q.shape->support(direction);
        const Vec3 c = box_support(q.cell_center, q.cell_half, -direction);
        simplex.push(s - c, s, c);
        simplex.bary[0] = 1.0;
    }
    Vec3 v = simplex.w[0];
    // Closer than this is rounding noise around 0: the two touch or overlap.
    const double zero = 1e-13 * (1.0 + q.cell_half.norm());
    for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
        const double vv = v.squaredNorm();
        if (vv <= zero * zero) {
            v.setZero();
            break;
        }
        const Vec3 s = q.shape->support(-v);
        const Vec3 c = box_support(q.cell_center, q.cell_half, v);
        const Vec3 w = s - c;
        const double vw = v.dot(w);
        // v.w / |v| is a lower bound of the distance (a separating plane).
        if (vw > 0.0 && vw * vw > q.stop_above * q.stop_above * vv) {
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
        if (q.stop_below >= 0.0 && v.squaredNorm() <= q.stop_below * q.stop_below) break;
    }
    result.distance = v.norm();
    result.intersecting = result.distance == 0.0;
    if (result.intersecting) result.simplex = simplex;
    set_witnesses(simplex, result);
    return result;
}

}  // namespace octoprox
