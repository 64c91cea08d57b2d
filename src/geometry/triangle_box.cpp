#include "geometry/triangle_box.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

// An axis shows the two intersecting only when its direction is well
// conditioned: a cross product at least this long, squared, against the
// product of its factors' squared lengths (edges at 1e-3 rad or more from
// parallel), so that the roundings of the edges turn it by 1e-13 rad at
// most.  Any axis, however short, shows them apart: a gap along any
// direction bounds the distance.
constexpr double kConditioned2 = 1e-6;

class AxisTest {
public:
    AxisTest(const Vec3 v[3], const Vec3 &center, const Vec3 &half, double limit, double margin)
        : half_(half), apart2_((limit + margin) * (limit + margin)), overlap2_(margin * margin) {
        for (int k = 0; k < 3; ++k) p_[k] = v[k] - center;
    }

    // Along `axis` (any length; `factors2` the squared lengths of the
    // vectors it is the cross product of, 1 for a box axis): true when it
    // shows the two apart; otherwise notes whether it shows them
    // overlapping by the margin.
    bool apart_along(const Vec3 &axis, double factors2) {
        const double length2 = axis.squaredNorm();
        const double a = axis.dot(p_[0]), b = axis.dot(p_[1]), c = axis.dot(p_[2]);
        const double low = std::min(a, std::min(b, c)), high = std::max(a, std::max(b, c));
        const double reach = std::fabs(axis.x()) * half_.x() + std::fabs(axis.y()) * half_.y() +
                             std::fabs(axis.z()) * half_.z();
        // The gap along the axis, times its length: > 0 when separated.
        const double gap = std::max(low - reach, -high - reach);
        if (gap > 0.0 && gap * gap > apart2_ * length2) return true;
        all_overlap_ = all_overlap_ && length2 > kConditioned2 * factors2 && gap < 0.0 &&
                       gap * gap > overlap2_ * length2;
        return false;
    }
    bool all_overlap() const { return all_overlap_; }
    const Vec3 &corner(int k) const { return p_[k]; }

private:
    Vec3 p_[3];  // the corners relative to the box's centre
    const Vec3 half_;
    const double apart2_, overlap2_;
    bool all_overlap_ = true;
};

}  // namespace

TriangleBoxAnswer triangle_box_sat(const Vec3 v[3], const Vec3 &center, const Vec3 &half, double limit,
                                   double margin) {
    AxisTest test(v, center, half, limit, margin);
    for (int axis = 0; axis < 3; ++axis)
        if (test.apart_along(Vec3::Unit(axis), 1.0)) return TriangleBoxAnswer::kApart;
    const Vec3 edges[3] = {test.corner(1) - test.corner(0), test.corner(2) - test.corner(1),
                           test.corner(0) - test.corner(2)};
    if (test.apart_along(edges[0].cross(edges[1]), edges[0].squaredNorm() * edges[1].squaredNorm()))
        return TriangleBoxAnswer::kApart;
    for (const Vec3 &e : edges) {
        // The box's axes crossed with the edge: x * e, y * e, z * e.
        const double e2 = e.squaredNorm();
        if (test.apart_along(Vec3(0.0, -e.z(), e.y()), e2) || test.apart_along(Vec3(e.z(), 0.0, -e.x()), e2) ||
            test.apart_along(Vec3(-e.y(), e.x(), 0.0), e2))
            return TriangleBoxAnswer::kApart;
    }
    return test.all_overlap() ? TriangleBoxAnswer::kIntersecting : TriangleBoxAnswer::kUndecided;
}

}  // namespace octoprox
