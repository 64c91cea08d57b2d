#include "self_filter/direction_bins.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

// Widening of every cone, for rounding in the bins' bounds.
constexpr double kConeSlack = 1e-6;

struct BinRect {
    int u0, u1, v0, v1;  // inclusive; empty when u0 > u1
};

// The range of a face coordinate x'/w' over the directions of the cone
// (unit axis with components w along the face's normal and x along the
// coordinate's axis, sine of the half angle s): the two planes through
// the origin tangent to the cone solve (w^2 - s^2) u^2 - 2 x w u + x^2 -
// s^2 = 0.  The cone lies in the face's open half-space (w > s).
void coordinate_range(double w, double x, double s, double &lo, double &hi) {
    const double a = w * w - s * s;
    const double root = s * std::sqrt(std::max(0.0, w * w + x * x - s * s));
    lo = (x * w - root) / a;
    hi = (x * w + root) / a;
}

int bin_floor(double coordinate) {
    const double scaled = std::floor((coordinate + 1.0) * 0.5 * DirectionBins::kSide);
    return static_cast<int>(std::clamp(scaled, 0.0, DirectionBins::kSide - 1.0));
}

// The bins of face (axis, negative) that the cone may reach.
BinRect face_rect(const Vec3 &axis_dir, double s, int axis, bool negative) {
    const double w = negative ? -axis_dir[axis] : axis_dir[axis];
    const double x = axis_dir[(axis + 1) % 3], y = axis_dir[(axis + 2) % 3];
    if (w <= -s) return BinRect{1, 0, 1, 0};  // behind the face's half-space
    if (w <= s) return BinRect{0, DirectionBins::kSide - 1, 0, DirectionBins::kSide - 1};  // reaches its plane
    double u_lo, u_hi, v_lo, v_hi;
    coordinate_range(w, x, s, u_lo, u_hi);
    coordinate_range(w, y, s, v_lo, v_hi);
    if (u_hi < -1.0 || u_lo > 1.0 || v_hi < -1.0 || v_lo > 1.0) return BinRect{1, 0, 1, 0};
    return BinRect{bin_floor(u_lo), bin_floor(u_hi), bin_floor(v_lo), bin_floor(v_hi)};
}

template <class Visit>
void for_each_bin(const Vec3 &axis_dir, double s, Visit &&visit) {
    for (int face = 0; face < 6; ++face) {
        const BinRect r = face_rect(axis_dir, s, face / 2, face % 2 == 1);
        for (int v = r.v0; v <= r.v1; ++v)
            for (int u = r.u0; u <= r.u1; ++u) visit(static_cast<uint32_t>((face * DirectionBins::kSide + v) * DirectionBins::kSide + u));
    }
}

}  // namespace

void DirectionBins::build(const Vec3 &origin, const std::vector<Ball> &balls) {
    start_.assign(kBins + 1, 0);
    ids_.clear();
    everywhere_.clear();
    std::vector<Vec3> axes(balls.size());
    std::vector<double> sines(balls.size(), -1.0);
    for (size_t i = 0; i < balls.size(); ++i) {
        const Vec3 offset = balls[i].center - origin;
        const double distance = offset.norm();
        const double s = balls[i].radius / distance + kConeSlack;
        if (!(s < 1.0)) {
            everywhere_.push_back(static_cast<uint32_t>(i));
            continue;
        }
        axes[i] = offset / distance, sines[i] = s;
        for_each_bin(axes[i], s, [&](uint32_t bin) { ++start_[bin + 1]; });
    }
    for (int bin = 0; bin < kBins; ++bin) start_[bin + 1] += start_[bin];
    ids_.resize(start_[kBins]);
    std::vector<uint32_t> next(start_.begin(), start_.end() - 1);
    for (size_t i = 0; i < balls.size(); ++i)
        if (sines[i] >= 0.0) for_each_bin(axes[i], sines[i], [&](uint32_t bin) { ids_[next[bin]++] = static_cast<uint32_t>(i); });
}

}  // namespace octoprox
