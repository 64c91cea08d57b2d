// Axis-aligned boxes in the map frame.
#pragma once

#include "geometry/pose.hpp"

#include <algorithm>

namespace octoprox {

struct Aabb {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = Vec3::Constant(-std::numeric_limits<double>::infinity());

    static Aabb from_center(const Vec3 &center, const Vec3 &half) { return {center - half, center + half}; }
    bool empty() const { return lo.x() > hi.x(); }
    Vec3 center() const { return 0.5 * (lo + hi); }
    Vec3 half_extent() const { return 0.5 * (hi - lo); }
    double longest_edge() const { return (hi - lo).maxCoeff(); }
    void grow(const Vec3 &p) { lo = lo.cwiseMin(p); hi = hi.cwiseMax(p); }
    void grow(const Aabb &b) { lo = lo.cwiseMin(b.lo); hi = hi.cwiseMax(b.hi); }
    void inflate(double margin) { lo.array() -= margin; hi.array() += margin; }
    // Closed boxes: touching faces overlap.
    bool overlaps(const Aabb &b) const {
        return lo.x() <= b.hi.x() && b.lo.x() <= hi.x() && lo.y() <= b.hi.y() && b.lo.y() <= hi.y() &&
               lo.z() <= b.hi.z() && b.lo.z() <= hi.z();
    }
    // Squared distance between the boxes (0 when they overlap).
    double squared_distance(const Aabb &b) const {
        const Vec3 gap = (b.lo - hi).cwiseMax(lo - b.hi).cwiseMax(0.0);
        return gap.squaredNorm();
    }
    // Every edge longer than zero: boxes that only share a face have an
    // intersection of no volume.
    bool has_volume() const { return (lo.array() < hi.array()).all(); }
    // The common part of the two boxes; without volume (or empty) when
    // they do not overlap.
    Aabb intersection(const Aabb &b) const { return Aabb{lo.cwiseMax(b.lo), hi.cwiseMin(b.hi)}; }
    double volume() const { return (hi - lo).cwiseMax(0.0).prod(); }
    double surface_area() const {
        const Vec3 e = (hi - lo).cwiseMax(0.0);
        return 2.0 * (e.x() * e.y() + e.y() * e.z() + e.z() * e.x());
    }
};

}  // namespace octoprox
