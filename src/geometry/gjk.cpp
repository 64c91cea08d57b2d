#include "geometry/gjk.hpp"

#include "geometry/gjk_loop.hpp"

namespace octoprox {

using gjk_detail::GjkLimits;
using gjk_detail::gjk_run;

GjkResult gjk_cell_distance(const GjkQuery &q) {
    GjkLimits limits;
    // Closer than this is rounding noise around 0: the two touch or overlap.
    limits.zero = 1e-13 * (1.0 + q.cell_half.norm());
    limits.stop_above = q.stop_above;
    limits.stop_below = q.stop_below;
    // Start from the direction between the centres: usually close to the answer.
    const Vec3 direction = q.cell_center - q.shape->support(Vec3::UnitX());
    return gjk_run([&](const Vec3 &d) { return q.shape->support(d); },
                   [&](const Vec3 &d) { return box_support(q.cell_center, q.cell_half, d); }, direction, limits);
}

GjkResult gjk_pair_distance(const GjkPairQuery &q) {
    GjkLimits limits;
    limits.zero = 1e-13 * (1.0 + q.scale);
    limits.stop_above = q.stop_above;
    limits.stop_below = q.stop_below;
    const Vec3 direction = q.b->support(-Vec3::UnitX()) - q.a->support(Vec3::UnitX());
    return gjk_run([&](const Vec3 &d) { return q.a->support(d); }, [&](const Vec3 &d) { return q.b->support(d); },
                   direction, limits);
}

}  // namespace octoprox
