#include "oracle_depth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
// Cross products shorter than this (relative to the edge) are parallel
// edges: their axis is one of the others.
constexpr double kParallel = 1e-9;

void add_axis(std::vector<Vec3> &axes, const Vec3 &axis, double length_scale) {
    const double norm = axis.norm();
    if (norm > kParallel * length_scale && norm > 0.0) axes.push_back(axis / norm);
}

std::vector<Vec3> candidate_axes(const ConvexCore &core) {
    std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
    for (const Vec3 &n : core.face_normals) add_axis(axes, n, 0.0);
    for (const Vec3 &d : core.edge_directions)
        for (int k = 0; k < 3; ++k) add_axis(axes, d.cross(Vec3::Unit(k)), d.norm());
    return axes;
}

ConvexCore point_core(const Vec3 &p) { return {{p}, {}, {}}; }

ConvexCore segment_core(const Vec3 &a, const Vec3 &b) { return {{a, b}, {}, {b - a}}; }

ConvexCore triangle_core(const Triangle &t) {
    return {{t.a, t.b, t.c}, {(t.b - t.a).cross(t.c - t.a)}, {t.b - t.a, t.c - t.b, t.a - t.c}};
}

ConvexCore box_core(const OrientedBox &box) {
    const std::array<Vec3, 8> corners = box_corners(box);
    const std::vector<Vec3> axes = {box.axes.col(0), box.axes.col(1), box.axes.col(2)};
    return {{corners.begin(), corners.end()}, axes, axes};
}

ConvexCore hull_core(const Polytope &hull) {
    const std::vector<Vec3> &v = hull.vertices;
    if (v.size() == 1) return point_core(v[0]);  // degenerate hulls
    if (v.size() == 2) return segment_core(v[0], v[1]);
    if (v.size() == 3) return triangle_core({v[0], v[1], v[2]});
    ConvexCore core;
    core.vertices = v;
    for (const auto &f : hull.faces) core.face_normals.push_back((v[f[1]] - v[f[0]]).cross(v[f[2]] - v[f[0]]));
    for (const Segment &e : polytope_edges(hull)) core.edge_directions.push_back(e.b - e.a);
    return core;
}

// The core of a solid shape (not a mesh, not a cylinder).
ConvexCore solid_core(const PlacedShape &s) {
    switch (s.kind) {
    case OPX_SHAPE_SPHERE: return point_core(s.point);
    case OPX_SHAPE_CAPSULE: return segment_core(s.segment.a, s.segment.b);
    case OPX_SHAPE_BOX: return box_core(s.box);
    default: return hull_core(s.hull);
    }
}

DepthAnswer piece_depth(const ConvexCore &core, double inflation, const Cell &cell, double core_distance_if_apart) {
    DepthAnswer answer;
    answer.exact = true;
    const double overlap = sat_overlap(core, cell, answer.normal);
    answer.core_overlaps = overlap >= 0.0;
    answer.depth = answer.core_overlaps ? overlap + inflation : inflation - core_distance_if_apart;
    if (!answer.core_overlaps) answer.normal = Vec3::Zero();
    return answer;
}

DepthAnswer mesh_depth(const PlacedShape &mesh, const Cell &cell) {
    DepthAnswer deepest;
    deepest.exact = true;
    deepest.depth = -kInfinity;
    for (const Triangle &t : mesh.triangles) {
        const ConvexCore core = triangle_core(t);
        Vec3 normal;
        const double apart = sat_overlap(core, cell, normal) >= 0.0 ? 0.0 : triangle_cell_distance(t, cell);
        const DepthAnswer d = piece_depth(core, mesh.inflation, cell, apart);
        if (d.depth > deepest.depth) deepest = d;
    }
    return deepest;
}

// The prism of oracle_fcl.hpp (vertices at `rim` from the axis) with its
// distinct face normals and edge directions only: the cap normal and the
// axis, one radial normal and one rim edge per side.
ConvexCore prism_core(const Polytope &prism, const Cylinder &c, int sides) {
    ConvexCore core;
    core.vertices = prism.vertices;
    const Vec3 axis = c.axes.col(2);
    core.face_normals.push_back(axis);
    core.edge_directions.push_back(axis);
    for (int k = 0; k < sides; ++k) {
        const double middle = (2 * k + 1) * kPi / sides;
        core.face_normals.push_back(c.axes.col(0) * std::cos(middle) + c.axes.col(1) * std::sin(middle));
        core.edge_directions.push_back(core.face_normals.back().cross(axis));
    }
    return core;
}

double prism_depth(const Cylinder &c, int sides, double rim, double inflation, const Cell &cell) {
    const Polytope prism = cylinder_prism(c, sides, rim);
    const ConvexCore core = prism_core(prism, c, sides);
    Vec3 normal;
    const double apart = sat_overlap(core, cell, normal) >= 0.0 ? 0.0 : polytope_cell_distance(prism, cell);
    return std::max(0.0, piece_depth(core, inflation, cell, apart).depth);
}

DepthAnswer cylinder_depth(const PlacedShape &shape, const Cell &cell, int sides) {
    const Cylinder &c = shape.cylinder;
    DepthAnswer answer;
    answer.low = prism_depth(c, sides, c.radius, shape.inflation, cell);
    answer.high = prism_depth(c, sides, c.radius / std::cos(kPi / sides), shape.inflation, cell);
    answer.depth = 0.5 * (answer.low + answer.high);
    return answer;
}

double cylinder_point_distance(const Cylinder &c, const Vec3 &p) {
    const Vec3 local = c.axes.transpose() * (p - c.center);
    const double radial = std::hypot(local.x(), local.y()) - c.radius;
    const double axial = std::abs(local.z()) - 0.5 * c.length;
    return Eigen::Vector2d(radial, axial).cwiseMax(0.0).norm();
}

double hull_point_distance(const Polytope &hull, const Vec3 &p) {
    const std::vector<Vec3> &v = hull.vertices;
    if (v.size() == 1) return (p - v[0]).norm();
    if (v.size() == 2) return (p - closest_point_on_segment(p, {v[0], v[1]})).norm();
    if (v.size() == 3) return point_triangle_distance(p, {v[0], v[1], v[2]});
    return point_polytope_distance(p, hull);
}

}  // namespace

double sat_overlap(const ConvexCore &core, const Cell &cell, Vec3 &normal) {
    double best = kInfinity;
    for (const Vec3 &n : candidate_axes(core)) {
        double low = kInfinity, high = -kInfinity;
        for (const Vec3 &v : core.vertices) {
            low = std::min(low, n.dot(v));
            high = std::max(high, n.dot(v));
        }
        const double middle = n.dot(cell.center), radius = cell.half * n.cwiseAbs().sum();
        const double back = high - (middle - radius);    // moving the core by -back * n
        const double forward = (middle + radius) - low;  // moving the core by +forward * n
        if (back < best) best = back, normal = n;
        if (forward < best) best = forward, normal = -n;
    }
    return best;
}

DepthAnswer padded_depth(const PlacedShape &shape, const Cell &cell, int prism_sides) {
    DepthAnswer answer;
    if (shape.kind == OPX_SHAPE_CYLINDER) return cylinder_depth(shape, cell, prism_sides);
    if (shape.kind == OPX_SHAPE_MESH) {
        answer = mesh_depth(shape, cell);
    } else {
        const ConvexCore core = solid_core(shape);
        Vec3 normal;
        const double apart = sat_overlap(core, cell, normal) >= 0.0 ? 0.0 : core_cell_distance(shape, cell);
        answer = piece_depth(core, shape.inflation, cell, apart);
    }
    answer.depth = answer.low = answer.high = std::max(0.0, answer.depth);
    return answer;
}

double core_cell_distance(const PlacedShape &shape, const Cell &cell) {
    return shape_cell_distance(shape, cell, kInfinity);
}

double core_point_distance(const PlacedShape &s, const Vec3 &p) {
    switch (s.kind) {
    case OPX_SHAPE_SPHERE: return (p - s.point).norm();
    case OPX_SHAPE_CAPSULE: return (p - closest_point_on_segment(p, s.segment)).norm();
    case OPX_SHAPE_BOX: return point_box_distance(p, s.box);
    case OPX_SHAPE_CYLINDER: return cylinder_point_distance(s.cylinder, p);
    case OPX_SHAPE_CONVEX: return hull_point_distance(s.hull, p);
    case OPX_SHAPE_MESH: {
        double best = kInfinity;
        for (const Triangle &t : s.triangles) best = std::min(best, point_triangle_distance(p, t));
        return best;
    }
    }
    return kInfinity;
}

PlacedShape translated(const PlacedShape &shape, const Vec3 &offset) {
    PlacedShape s = shape;
    s.point += offset;
    s.segment.a += offset, s.segment.b += offset;
    s.box.center += offset;
    s.cylinder.center += offset;
    for (Vec3 &v : s.hull.vertices) v += offset;
    for (Triangle &t : s.triangles) t.a += offset, t.b += offset, t.c += offset;
    s.bounds_min += offset, s.bounds_max += offset;
    return s;
}

}  // namespace oracle
