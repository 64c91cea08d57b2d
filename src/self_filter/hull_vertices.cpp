#include "self_filter/hull_vertices.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

constexpr size_t kWholeBelow = 33;   // sets this small come back whole
constexpr int kDirections = 64;

struct Plane {
    Vec3 normal;  // unit, outward
    double offset;
};

// Indices of the points extreme along kDirections directions spread over
// the sphere (a Fibonacci lattice): each is a vertex of the hull.
std::vector<size_t> extreme_points(const std::vector<Vec3> &points) {
    std::vector<size_t> extremes;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < kDirections; ++k) {
        const double z = 1.0 - 2.0 * (k + 0.5) / kDirections, r = std::sqrt(1.0 - z * z);
        const Vec3 d(r * std::cos(golden * k), r * std::sin(golden * k), z);
        size_t best = 0;
        for (size_t i = 1; i < points.size(); ++i)
            if (points[i].dot(d) > points[best].dot(d)) best = i;
        extremes.push_back(best);
    }
    std::sort(extremes.begin(), extremes.end());
    extremes.erase(std::unique(extremes.begin(), extremes.end()), extremes.end());
    return extremes;
}

// The planes of the extremes' hull: every plane through three of them with
// all of them on one side (within `slack`).  Every facet is among them.
std::vector<Plane> facet_planes(const std::vector<Vec3> &e, double slack) {
    std::vector<Plane> planes;
    for (size_t a = 0; a < e.size(); ++a)
        for (size_t b = a + 1; b < e.size(); ++b)
            for (size_t c = b + 1; c < e.size(); ++c) {
                Vec3 n = (e[b] - e[a]).cross(e[c] - e[a]);
                const double length = n.norm();
                if (!(length > 0.0)) continue;
                n /= length;
                bool above = false, below = false;
                for (const Vec3 &p : e) {
                    const double side = n.dot(p - e[a]);
                    above |= side > slack, below |= side < -slack;
                    if (above && below) break;
                }
                if (above && below) continue;
                if (above) n = -n;
                planes.push_back(Plane{n, n.dot(e[a])});
            }
    return planes;
}

}  // namespace

std::vector<Vec3> hull_vertex_superset(const std::vector<Vec3> &points) {
    if (points.size() < kWholeBelow) return points;
    Aabb box;
    for (const Vec3 &p : points) box.grow(p);
    const double scale = std::max(box.longest_edge(), 1e-300);
    std::vector<Vec3> extremes;
    for (const size_t i : extreme_points(points)) extremes.push_back(points[i]);
    const std::vector<Plane> planes = facet_planes(extremes, 1e-12 * scale);
    if (planes.empty()) return points;  // the extremes are flat: keep all
    // Strictly inside every plane, by far more than rounding: inside the
    // extremes' hull, so no vertex of the whole hull.
    const double margin = 1e-9 * scale;
    std::vector<Vec3> kept;
    for (const Vec3 &p : points) {
        bool inside = true;
        for (const Plane &plane : planes)
            if (!(plane.normal.dot(p) - plane.offset < -margin)) {
                inside = false;
                break;
            }
        if (!inside) kept.push_back(p);
    }
    return kept;
}

}  // namespace octoprox
