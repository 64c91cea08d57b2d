#include "geometry/cylinder_distance.hpp"

#include <cmath>

namespace octoprox {
namespace {

// The segment's nearest point must be this far inside it (a fraction of
// its length) to count as inside: far above rounding, so the pair's
// direction is square to the axis.
constexpr double kInsideMargin = 1e-9;

// Beyond a cap (normal `outward`, its plane at height `plane` along it):
// true, with `result` set, when that decides the distance.
bool beyond_cap(const Convex &cylinder, const GjkQuery &q, const Vec3 &outward, double plane, GjkResult &result) {
    const Vec3 vertex = box_support(q.cell_center, q.cell_half, -outward);  // the box's nearest to the plane
    const double gap = outward.dot(vertex) - plane;
    if (!(gap > 0.0)) return false;
    if (gap > q.stop_above) {  // a lower bound above the caller's interest
        result.distance = gap;
        return true;
    }
    const Vec3 from_axis = vertex - cylinder.center;
    const Vec3 radial = from_axis - from_axis.dot(outward) * outward;
    if (radial.squaredNorm() > cylinder.half.x() * cylinder.half.x()) return false;  // nearest at the rim
    result.distance = gap;
    result.on_cell = vertex;
    result.on_shape = vertex - gap * outward;
    return true;
}

// Beside the round side: true, with `result` set, when that decides it.
bool beside_side(const Convex &cylinder, const GjkQuery &q, GjkResult &result) {
    const Vec3 axis = cylinder.axes.col(2);
    const double radius = cylinder.half.x(), half_length = cylinder.half.z();
    Convex segment;
    segment.kind = ConvexKind::kSegment;
    segment.v[0] = cylinder.center - half_length * axis;
    segment.v[1] = cylinder.center + half_length * axis;
    GjkQuery along = q;
    along.shape = &segment;
    along.stop_above = q.stop_above + radius;
    const GjkResult core = gjk_cell_distance(along);
    if (core.intersecting || !(core.distance > radius)) return false;  // the cylinder may overlap the box
    if (core.distance > along.stop_above) {  // the capsule, hence the cylinder, is beyond interest
        result.distance = core.distance - radius;
        return true;
    }
    const double t = (core.on_shape - segment.v[0]).dot(axis) / (2.0 * half_length);
    if (!(t > kInsideMargin && t < 1.0 - kInsideMargin)) return false;  // nearest at a cap or the rim
    const Vec3 direction = (core.on_cell - core.on_shape) / core.distance;
    result.distance = core.distance - radius;
    result.on_cell = core.on_cell;
    result.on_shape = core.on_shape + radius * direction;
    return true;
}

}  // namespace

GjkResult cylinder_cell_distance(const GjkQuery &q, CylinderPath *path) {
    const Convex &cylinder = *q.shape;
    const Vec3 axis = cylinder.axes.col(2);
    const double middle = axis.dot(cylinder.center), half_length = cylinder.half.z();
    GjkResult result;
    CylinderPath taken = CylinderPath::kGjk;
    if (half_length > 0.0) {  // a flat disk has no side: GJK
        if (beyond_cap(cylinder, q, axis, middle + half_length, result) ||
            beyond_cap(cylinder, q, -axis, -middle + half_length, result))
            taken = CylinderPath::kCap;
        else if (beside_side(cylinder, q, result))
            taken = CylinderPath::kSide;
    }
    if (taken == CylinderPath::kGjk) result = gjk_cell_distance(q);
    if (path != nullptr) *path = taken;
    return result;
}

}  // namespace octoprox
