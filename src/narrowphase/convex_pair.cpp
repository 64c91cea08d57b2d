#include "narrowphase/convex_pair.hpp"

#include "geometry/epa.hpp"
#include "geometry/gjk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {
namespace {

struct CoreDistance {
    double distance = 0.0;
    bool intersecting = false;
    Vec3 on_a = Vec3::Zero(), on_b = Vec3::Zero();
    Simplex simplex;  // GJK's, when intersecting
};

// The cores' distance; two points need no GJK.  With a finite stop_above
// the answer may be a lower bound above it (no witnesses then).
CoreDistance core_distance(const Convex &a, const Convex &b, double scale, double stop_above, double stop_below) {
    CoreDistance d;
    if (a.kind == ConvexKind::kPoint && b.kind == ConvexKind::kPoint) {
        d.distance = (b.center - a.center).norm();
        d.on_a = a.center, d.on_b = b.center;
        return d;
    }
    GjkPairQuery query;
    query.a = &a, query.b = &b, query.scale = scale;
    query.stop_above = stop_above, query.stop_below = stop_below;
    const GjkResult r = gjk_pair_distance(query);
    d.distance = r.intersecting ? 0.0 : r.distance;
    d.intersecting = r.intersecting;
    d.on_a = r.on_shape, d.on_b = r.on_cell;
    d.simplex = r.simplex;
    return d;
}

// A point both overlapping cores hold: GJK ended on a tetrahedron of
// differences w_i = s_i - c_i around the origin; the origin's barycentric
// weights give sum l_i s_i = sum l_i c_i, a convex combination of points of
// each core.  False when the tetrahedron is flat (the cores only touch).
bool common_point(const Simplex &simplex, Vec3 &out) {
    if (simplex.size != 4) return false;
    Eigen::Matrix3d edges;
    for (int i = 0; i < 3; ++i) edges.col(i) = simplex.w[i + 1] - simplex.w[0];
    const double det = edges.determinant();
    if (!(std::fabs(det) > 1e-30)) return false;
    const Vec3 mu = edges.inverse() * (-simplex.w[0]);
    const double l0 = 1.0 - mu.sum();
    if (l0 < -1e-9 || (mu.array() < -1e-9).any()) return false;
    out = l0 * simplex.s[0] + mu[0] * simplex.s[1] + mu[1] * simplex.s[2] + mu[2] * simplex.s[3];
    return true;
}

// Cores that overlap: EPA gives their depth, normal and deepest points.
PiecePairPenetration overlapping_cores(const InflatedPiece &a, const InflatedPiece &b, double scale,
                                       const Simplex &simplex) {
    const Penetration e = epa_pair_penetration(*a.core, *b.core, scale, simplex);
    PiecePairPenetration p;
    p.depth = e.depth + a.inflation + b.inflation;
    p.normal = e.normal;
    p.on_a = e.on_shape + a.inflation * e.normal;
    p.on_b = e.on_cell - b.inflation * e.normal;
    return p;
}

// How far triangle t lies wholly beyond the plane of triangle p, on either
// side (0 when it reaches or crosses it): a lower bound of their distance.
// Cheap, and most pairs of triangles whose boxes meet lie apart across
// one of their planes.
double plane_gap(const Convex &p, const Convex &t) {
    const Vec3 n = (p.v[1] - p.v[0]).cross(p.v[2] - p.v[0]);
    const double length = n.norm();
    if (!(length > 0.0)) return 0.0;
    double low = std::numeric_limits<double>::infinity(), high = -low;
    for (int k = 0; k < 3; ++k) {
        const double h = n.dot(t.v[k] - p.v[0]);
        low = std::min(low, h), high = std::max(high, h);
    }
    return std::max({0.0, low, -high}) / length;
}

// A lower bound of the cores' distance: for two triangles, the larger of
// their plane gaps; 0 otherwise.
double core_lower_bound(const Convex &a, const Convex &b) {
    if (a.kind != ConvexKind::kTriangle || b.kind != ConvexKind::kTriangle) return 0.0;
    return std::max(plane_gap(a, b), plane_gap(b, a));
}

}  // namespace

bool pieces_within(const InflatedPiece &a, const InflatedPiece &b, double limit, double scale) {
    const double reach = limit + a.inflation + b.inflation;
    if (core_lower_bound(*a.core, *b.core) > reach) return false;
    const CoreDistance d = core_distance(*a.core, *b.core, scale, reach, reach);
    return d.intersecting || d.distance <= reach;
}

bool piece_pair_distance(const InflatedPiece &a, const InflatedPiece &b, double scale, double bound,
                         PiecePairDistance &out) {
    const double balls = a.inflation + b.inflation;
    if (core_lower_bound(*a.core, *b.core) - balls >= bound) return false;
    const CoreDistance d = core_distance(*a.core, *b.core, scale, bound + balls, -1.0);
    if (!d.intersecting && d.distance - balls >= bound) return false;
    if (d.intersecting) {
        out.distance = 0.0;
        if (!common_point(d.simplex, out.on_a)) {
            // Touching (a smaller simplex): GJK's witness; a flat
            // tetrahedron: the middle of EPA's deepest points.
            if (d.simplex.size < 4) {
                out.on_a = d.on_a;
            } else {
                const PiecePairPenetration p = overlapping_cores(a, b, scale, d.simplex);
                out.on_a = 0.5 * (p.on_a + p.on_b);
            }
        }
        out.on_b = out.on_a;
        return true;
    }
    const Vec3 gap = d.on_b - d.on_a;
    if (d.distance > balls) {
        out.distance = d.distance - balls;
        out.on_a = d.on_a + gap * (a.inflation / d.distance);
        out.on_b = d.on_b - gap * (b.inflation / d.distance);
    } else {
        // The balls overlap: one point, splitting the gap as the radii do.
        out.distance = 0.0;
        out.on_a = out.on_b = balls > 0.0 ? Vec3(d.on_a + gap * (a.inflation / balls)) : d.on_a;
    }
    return true;
}

PiecePairPenetration piece_pair_penetration(const InflatedPiece &a, const InflatedPiece &b, double scale) {
    const CoreDistance d = core_distance(*a.core, *b.core, scale, std::numeric_limits<double>::infinity(), -1.0);
    if (d.intersecting) return overlapping_cores(a, b, scale, d.simplex);
    PiecePairPenetration p;
    // Disjoint cores: the balls overlap along the line between the witnesses.
    p.normal = d.distance > 0.0 ? Vec3((d.on_b - d.on_a) / d.distance) : Vec3::UnitX();
    p.depth = a.inflation + b.inflation - d.distance;
    p.on_a = d.on_a + a.inflation * p.normal;
    p.on_b = d.on_b - b.inflation * p.normal;
    return p;
}

}  // namespace octoprox
