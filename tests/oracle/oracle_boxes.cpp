#include "oracle_boxes.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;

using PointDistance = std::function<double(const Vec3 &)>;

std::array<Vec3, 8> corners_of(const AlignedBox &box) {
    std::array<Vec3, 8> corners;
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k) corners[i][k] = ((i >> k) & 1) ? box.hi[k] : box.lo[k];
    return corners;
}

// Corners whose indices differ in one bit share an edge.
std::vector<Segment> edges_of(const std::array<Vec3, 8> &corners) {
    std::vector<Segment> edges;
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
            if (!((i >> k) & 1)) edges.push_back({corners[i], corners[i | (1 << k)]});
    return edges;
}

// Closed intervals sharing an end point are not separated.
bool axis_separates(const Vec3 &axis, const std::vector<Vec3> &vertices, const AlignedBox &box) {
    double low = kInfinity, high = -kInfinity;
    for (const Vec3 &v : vertices) {
        low = std::min(low, axis.dot(v));
        high = std::max(high, axis.dot(v));
    }
    const double middle = axis.dot(box.center());
    const double radius = axis.cwiseAbs().dot(box.half());
    return high < middle - radius || low > middle + radius;
}

bool intersects(const std::vector<Vec3> &vertices, const std::vector<Vec3> &normals,
                const std::vector<Segment> &edges, const AlignedBox &box) {
    std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
    axes.insert(axes.end(), normals.begin(), normals.end());
    for (const Segment &e : edges)
        for (int k = 0; k < 3; ++k) axes.push_back((e.b - e.a).cross(Vec3::Unit(k)));
    for (const Vec3 &axis : axes)
        if (axis.squaredNorm() >= 1e-24 && axis_separates(axis, vertices, box)) return false;
    return true;
}

double feature_distance(const std::vector<Vec3> &vertices, const std::vector<Segment> &edges,
                        const PointDistance &to_piece, const AlignedBox &box) {
    double best = kInfinity;
    const std::array<Vec3, 8> corners = corners_of(box);
    for (const Vec3 &v : vertices) best = std::min(best, point_aligned_distance(v, box));
    for (const Vec3 &c : corners) best = std::min(best, to_piece(c));
    for (const Segment &e : edges)
        for (const Segment &f : edges_of(corners)) best = std::min(best, segment_segment_distance(e, f));
    return best;
}

double piece_distance(const std::vector<Vec3> &vertices, const std::vector<Vec3> &normals,
                      const std::vector<Segment> &edges, const PointDistance &to_piece, const AlignedBox &box) {
    if (intersects(vertices, normals, edges, box)) return 0.0;
    return feature_distance(vertices, edges, to_piece, box);
}

double fcl_cylinder_distance(const Cylinder &c, const AlignedBox &box, fcl::GJKSolverType solver) {
    const fcl::Cylinderd cylinder(c.radius, c.length);
    const Vec3 size = box.hi - box.lo;
    const fcl::Boxd fcl_box(size.x(), size.y(), size.z());
    fcl::Transform3d cylinder_pose = fcl::Transform3d::Identity(), box_pose = fcl::Transform3d::Identity();
    cylinder_pose.linear() = c.axes;
    cylinder_pose.translation() = c.center;
    box_pose.translation() = box.center();
    fcl::DistanceRequestd request;
    request.gjk_solver_type = solver;
    request.distance_tolerance = 1e-12;
    fcl::DistanceResultd result;
    return std::max(0.0, fcl::distance(&cylinder, cylinder_pose, &fcl_box, box_pose, request, result));
}

}  // namespace

AlignedBox aligned_box_of(const Cell &cell) {
    return {cell.center - Vec3::Constant(cell.half), cell.center + Vec3::Constant(cell.half)};
}

AlignedBox intersect(const AlignedBox &a, const AlignedBox &b, bool &empty) {
    const AlignedBox out{a.lo.cwiseMax(b.lo), a.hi.cwiseMin(b.hi)};
    empty = (out.lo.array() > out.hi.array()).any();
    return out;
}

double point_aligned_distance(const Vec3 &p, const AlignedBox &box) {
    return (box.lo - p).cwiseMax(p - box.hi).cwiseMax(0.0).norm();
}

double segment_aligned_distance(const Segment &s, const AlignedBox &box) {
    return piece_distance({s.a, s.b}, {}, {s},
                          [&](const Vec3 &p) { return (p - closest_point_on_segment(p, s)).norm(); }, box);
}

double triangle_aligned_distance(const Triangle &t, const AlignedBox &box) {
    const Vec3 normal = (t.b - t.a).cross(t.c - t.a);
    return piece_distance({t.a, t.b, t.c}, {normal}, {{t.a, t.b}, {t.b, t.c}, {t.c, t.a}},
                          [&](const Vec3 &p) { return point_triangle_distance(p, t); }, box);
}

double oriented_aligned_distance(const OrientedBox &b, const AlignedBox &box) {
    const std::array<Vec3, 8> corners = box_corners(b);
    const std::vector<Vec3> normals = {b.axes.col(0), b.axes.col(1), b.axes.col(2)};
    return piece_distance({corners.begin(), corners.end()}, normals, edges_of(corners),
                          [&](const Vec3 &p) { return point_box_distance(p, b); }, box);
}

double polytope_aligned_distance(const Polytope &hull, const AlignedBox &box) {
    std::vector<Vec3> normals;
    for (const auto &f : hull.faces) {
        const Vec3 &a = hull.vertices[f[0]], &b = hull.vertices[f[1]], &c = hull.vertices[f[2]];
        normals.push_back((b - a).cross(c - a));
    }
    return piece_distance(hull.vertices, normals, polytope_edges(hull),
                          [&](const Vec3 &p) { return point_polytope_distance(p, hull); }, box);
}

double cylinder_aligned_distance(const Cylinder &c, const AlignedBox &box) {
    const double indep = fcl_cylinder_distance(c, box, fcl::GST_INDEP);
    const double libccd = fcl_cylinder_distance(c, box, fcl::GST_LIBCCD);
    if (std::abs(indep - libccd) <= 1e-7) return indep;
    double low = 0.0, high = 0.0;  // exact prism brackets
    for (int sides : {256, 1024}) {
        high = polytope_aligned_distance(cylinder_prism(c, sides, c.radius), box);
        low = polytope_aligned_distance(cylinder_prism(c, sides, c.radius / std::cos(kPi / sides)), box);
        if (high - low < kCurvedAmbiguity) break;
    }
    return 0.5 * (low + high);
}

double shape_aligned_distance(const PlacedShape &s, const AlignedBox &box) {
    switch (s.kind) {
    case OPX_SHAPE_SPHERE: return point_aligned_distance(s.point, box);
    case OPX_SHAPE_CAPSULE: return segment_aligned_distance(s.segment, box);
    case OPX_SHAPE_BOX: return oriented_aligned_distance(s.box, box);
    case OPX_SHAPE_CYLINDER: return cylinder_aligned_distance(s.cylinder, box);
    case OPX_SHAPE_CONVEX: {
        const std::vector<Vec3> &v = s.hull.vertices;  // degenerate hulls first
        if (v.size() == 1) return point_aligned_distance(v[0], box);
        if (v.size() == 2) return segment_aligned_distance({v[0], v[1]}, box);
        if (v.size() == 3) return triangle_aligned_distance({v[0], v[1], v[2]}, box);
        return polytope_aligned_distance(s.hull, box);
    }
    case OPX_SHAPE_MESH: {
        double best = kInfinity;
        for (const Triangle &t : s.triangles) best = std::min(best, triangle_aligned_distance(t, box));
        return best;
    }
    }
    return kInfinity;
}

}  // namespace oracle
