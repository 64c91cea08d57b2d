#include "filter_oracle.hpp"

#include <algorithm>
#include <cmath>

namespace filter_oracle {
namespace {

constexpr double kEntryGap = 1e-12;     // the trace stops this close to the padded robot
constexpr double kMinStep = 1e-9;       // metres: a grazing trace still moves on
constexpr double kAmbiguous = 1e-8;     // metres from flipping a verdict
constexpr double kGrazingProbe = 1e-6;  // metres past an entry: a ray entering deeper is no graze
constexpr int kMaxSteps = 200000;
constexpr double kTraceLimit = 0.05;  // metres: farther solids step by their lower bounds
constexpr double kEndLimit = 0.011;   // metres: end gaps known exactly up to here

double capsule_distance(const Vec3 &p, double half_length, double radius) {
    const Vec3 axis_point(0.0, 0.0, std::clamp(p.z(), -half_length, half_length));
    return std::max(0.0, (p - axis_point).norm() - radius);
}

double primitive_distance(const render::Primitive &solid, const Vec3 &x) {
    const Vec3 p = solid.map_from_shape.inverse() * x;
    switch (solid.kind) {
    case OPX_SHAPE_SPHERE: return std::max(0.0, p.norm() - solid.radius);
    case OPX_SHAPE_BOX: return (p.cwiseAbs() - solid.half_size).cwiseMax(0.0).norm();
    case OPX_SHAPE_CYLINDER:
        return std::hypot(std::max(0.0, std::hypot(p.x(), p.y()) - solid.radius),
                          std::max(0.0, std::fabs(p.z()) - solid.half_length));
    case OPX_SHAPE_CAPSULE: return capsule_distance(p, solid.half_length, solid.radius);
    default: return INFINITY;  // convex hulls are surface solids here
    }
}

std::vector<Vec3> vertices_of(const std::vector<Triangle> &triangles) {
    std::vector<Vec3> points;
    for (const Triangle &t : triangles) points.insert(points.end(), {t.a, t.b, t.c});
    std::sort(points.begin(), points.end(), [](const Vec3 &a, const Vec3 &b) {
        return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    return points;
}

std::vector<Triangle> oracle_triangles(const std::vector<render::Triangle> &triangles) {
    std::vector<Triangle> out;
    for (const render::Triangle &t : triangles) out.push_back(Triangle{t.a, t.b, t.c});
    return out;
}

void set_bound(Solid &solid, const Vec3 &center, const std::vector<Vec3> &points) {
    solid.center = center;
    for (const Vec3 &p : points) solid.bound = std::max(solid.bound, (p - center).norm());
}

// Whether the segment origin -> end comes within `reach` of `center`.
bool segment_near(const Vec3 &origin, const Vec3 &end, const Vec3 &center, double reach) {
    const Vec3 dir = end - origin;
    const double length2 = dir.squaredNorm();
    const double s = length2 > 0.0 ? std::clamp((center - origin).dot(dir) / length2, 0.0, 1.0) : 0.0;
    return (origin + s * dir - center).norm() <= reach;
}

}  // namespace

double Solid::distance_below(const Vec3 &x, double limit) const {
    return surface ? surface->distance_below(x, limit) : primitive_distance(primitive, x);
}

double Solid::lower_bound(const Vec3 &x) const {
    const double ball = (x - center).norm() - bound;
    return surface ? std::max(ball, surface->box_gap(x)) : ball;
}

OracleRobot::OracleRobot(const opx_linkset *robot, const FilterSettings &settings) {
    const render::RobotSolids read = render::read_robot_solids(robot);
    const auto link_on = [&](uint32_t link) { return settings.enabled.empty() || settings.enabled.at(link); };
    const auto padding = [&](uint32_t link) {
        return settings.robot_padding + (settings.link_padding.empty() ? 0.0 : settings.link_padding.at(link));
    };
    for (const render::Primitive &p : read.primitives) {
        if (!link_on(p.link)) continue;
        Solid solid;
        solid.kind = p.kind, solid.primitive = p, solid.padding = padding(p.link);
        if (p.kind == OPX_SHAPE_CONVEX)
            solid.surface = std::make_shared<SurfaceSolid>(convex_hull(p.corners), true);
        set_bound(solid, p.map_from_shape.translation(), p.corners);
        solids_.push_back(solid);
    }
    for (const render::Mesh &mesh : read.meshes) {
        if (!link_on(mesh.link) || mesh.triangles.empty()) continue;
        std::vector<Triangle> triangles = oracle_triangles(mesh.triangles);
        const bool closed = is_closed(triangles);
        const std::vector<Vec3> points = vertices_of(triangles);
        Solid solid;
        solid.kind = OPX_SHAPE_MESH, solid.padding = padding(mesh.link);
        solid.surface = std::make_shared<SurfaceSolid>(closed ? std::move(triangles) : convex_hull(points), !closed);
        ++(closed ? closed_meshes_ : hull_meshes_);
        set_bound(solid, 0.5 * (solid.surface->box_min() + solid.surface->box_max()), points);
        solids_.push_back(solid);
    }
}

// Solids whose lower bound is at least the best gap so far are skipped;
// the result is exact below `limit` and a lower bound otherwise.
double OracleRobot::gap_over(const std::vector<size_t> &which, const Vec3 &x, double limit) const {
    double best = limit, skipped = INFINITY;
    for (size_t i : which) {
        const Solid &s = solids_[i];
        const double bound = s.lower_bound(x) - s.padding;
        if (bound >= best) {
            skipped = std::min(skipped, bound);
            continue;
        }
        best = std::min(best, s.distance_below(x, best + s.padding) - s.padding);
    }
    return std::min(best, skipped);
}

double OracleRobot::gap(const Vec3 &x, double limit) const {
    std::vector<size_t> all(solids_.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = i;
    return gap_over(all, x, limit);
}

// Sphere tracing from origin to end: t of the first point within kEntryGap
// of the padded solids `which` (bisection when a step overshoots).
bool OracleRobot::trace(const std::vector<size_t> &which, const Vec3 &origin, const Vec3 &end, double &t,
                        bool &ambiguous) const {
    const Vec3 dir = end - origin;
    const double length = dir.norm();
    std::vector<size_t> near;
    for (size_t i : which)
        if (segment_near(origin, end, solids_[i].center, solids_[i].bound + solids_[i].padding + kAmbiguous))
            near.push_back(i);
    if (near.empty() || length == 0.0) return false;
    double min_gap = INFINITY, previous = 0.0;
    t = 0.0;
    for (int step = 0; step < kMaxSteps; ++step) {
        const double g = gap_over(near, origin + t * dir, kTraceLimit);
        if (g <= kEntryGap) {
            for (double lo = previous, hi = t; g < 0.0 && (hi - lo) * length > 1e-13;) {
                const double mid = 0.5 * (lo + hi);
                (gap_over(near, origin + mid * dir, kTraceLimit) <= kEntryGap ? hi : lo) = mid;
                t = hi;
            }
            const double probe = std::min(1.0, t + kGrazingProbe / length);
            if (gap_over(near, origin + probe * dir, kTraceLimit) > -kAmbiguous) ambiguous = true;
            return true;
        }
        min_gap = std::min(min_gap, g);
        if (t >= 1.0) break;
        previous = t;
        t = std::min(1.0, t + std::max(g, kMinStep) / length);
    }
    if (min_gap < kAmbiguous) ambiguous = true;
    return false;
}

Verdict OracleRobot::judge(const std::vector<size_t> &shadowing, const Vec3 &origin, const Vec3 &end,
                           bool range_cut) const {
    Verdict v;
    v.range_cut = range_cut;
    const double end_gap = range_cut ? INFINITY : gap(end, kEndLimit);
    v.end_gap = end_gap;
    v.ambiguous = std::fabs(end_gap) <= kAmbiguous;
    double t = 1.0;
    const bool entered = trace(shadowing, origin, end, t, v.ambiguous);
    if (end_gap <= 0.0) v.kind = Verdict::kOnRobot, v.t = entered ? t : 0.0;
    else if (entered) v.kind = Verdict::kShadowed, v.t = t;
    return v;
}

std::vector<size_t> OracleRobot::shadowing_solids(const Vec3 &origin) const {
    std::vector<size_t> shadowing;  // solids whose padded volume does not hold the sensor
    for (size_t i = 0; i < solids_.size(); ++i)
        if (solids_[i].distance(origin) > solids_[i].padding) shadowing.push_back(i);
    return shadowing;
}

size_t OracleRobot::solids_holding(const Vec3 &origin) const {
    return solids_.size() - shadowing_solids(origin).size();
}

std::vector<Verdict> OracleRobot::judge_frame(const Vec3 &origin, const std::vector<Vec3> &ends,
                                              const std::vector<bool> &range_cut) const {
    const std::vector<size_t> shadowing = shadowing_solids(origin);
    std::vector<Verdict> verdicts;
    verdicts.reserve(ends.size());
    for (size_t i = 0; i < ends.size(); ++i)
        verdicts.push_back(judge(shadowing, origin, ends[i], !range_cut.empty() && range_cut[i]));
    return verdicts;
}

}  // namespace filter_oracle
