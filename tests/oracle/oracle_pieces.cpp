#include "oracle_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

void set_bounds(Piece &piece) {
    piece.low = Vec3::Constant(kInfinity), piece.high = Vec3::Constant(-kInfinity);
    for (const Vec3 &v : piece.vertices) piece.low = piece.low.cwiseMin(v), piece.high = piece.high.cwiseMax(v);
}

std::vector<Segment> triangle_edges(const Triangle &t) { return {{t.a, t.b}, {t.b, t.c}, {t.c, t.a}}; }

}  // namespace

Piece point_piece(const Vec3 &p) {
    Piece piece;
    piece.kind = Piece::kPoint, piece.vertices = {p};
    set_bounds(piece);
    return piece;
}

Piece segment_piece(const Segment &s) {
    Piece piece;
    piece.kind = Piece::kSegment, piece.vertices = {s.a, s.b}, piece.edges = {s};
    set_bounds(piece);
    return piece;
}

Piece triangle_piece(const Triangle &t) {
    Piece piece;
    piece.kind = Piece::kTriangle, piece.vertices = {t.a, t.b, t.c};
    piece.edges = triangle_edges(t), piece.faces = {t};
    set_bounds(piece);
    return piece;
}

Piece box_piece(const OrientedBox &box) {
    Polytope hull;
    const std::array<Vec3, 8> corners = box_corners(box);
    hull.vertices.assign(corners.begin(), corners.end());
    // Corner i has bit k set on the +k side (box_corners); each face is a
    // quad of the four corners sharing one bit, split in two triangles.
    static const int kQuads[6][4] = {{0, 1, 3, 2}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 3, 7, 5}};
    for (const auto &q : kQuads) hull.faces.push_back({q[0], q[1], q[2]}), hull.faces.push_back({q[0], q[2], q[3]});
    Piece piece = polytope_piece(hull);
    piece.kind = Piece::kBox, piece.box = box;
    return piece;
}

Piece polytope_piece(const Polytope &hull) {
    const std::vector<Vec3> &v = hull.vertices;
    if (v.size() == 1) return point_piece(v[0]);
    if (v.size() == 2) return segment_piece({v[0], v[1]});
    if (v.size() == 3) return triangle_piece({v[0], v[1], v[2]});
    Piece piece;
    piece.kind = Piece::kPolytope, piece.hull = hull, piece.vertices = v;
    piece.edges = polytope_edges(hull);
    for (const auto &f : hull.faces) piece.faces.push_back({v[f[0]], v[f[1]], v[f[2]]});
    set_bounds(piece);
    return piece;
}

Piece cylinder_piece(const Cylinder &cylinder) {
    Piece piece;
    piece.kind = Piece::kCylinder, piece.cylinder = cylinder;
    // The rim circles' extent along world axis k is r * sqrt(1 - axis_k^2).
    const Vec3 axis = cylinder.axes.col(2);
    const Vec3 rim = (Vec3::Ones() - axis.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt() * cylinder.radius;
    const Vec3 reach = axis.cwiseAbs() * (0.5 * cylinder.length) + rim;
    piece.low = cylinder.center - reach, piece.high = cylinder.center + reach;
    return piece;
}

double point_piece_distance(const Vec3 &p, const Piece &piece) {
    switch (piece.kind) {
    case Piece::kCylinder: return point_cylinder_distance(p, piece.cylinder);
    case Piece::kPoint: return (p - piece.vertices[0]).norm();
    case Piece::kSegment: return (p - closest_point_on_segment(p, piece.edges[0])).norm();
    case Piece::kTriangle: return point_triangle_distance(p, piece.faces[0]);
    case Piece::kBox: return point_box_distance(p, piece.box);
    case Piece::kPolytope: return point_polytope_distance(p, piece.hull);
    }
    return kInfinity;
}

// A segment crossing the triangle's plane inside it is at distance 0;
// otherwise the nearest pair is an end point and the triangle, or the
// segment and an edge.
double segment_triangle_distance(const Segment &s, const Triangle &t) {
    double best = std::min(point_triangle_distance(s.a, t), point_triangle_distance(s.b, t));
    for (const Segment &edge : triangle_edges(t)) best = std::min(best, segment_segment_distance(s, edge));
    const Vec3 normal = (t.b - t.a).cross(t.c - t.a);
    const double da = normal.dot(s.a - t.a), db = normal.dot(s.b - t.a);
    if (normal.squaredNorm() > 0.0 && da * db < 0.0) {
        const Vec3 crossing = s.a + (s.b - s.a) * (da / (da - db));
        best = std::min(best, point_triangle_distance(crossing, t));
    }
    return best;
}

double bounds_distance(const Piece &a, const Piece &b) {
    return (a.low - b.high).cwiseMax(b.low - a.high).cwiseMax(0.0).norm();
}

double piece_distance(const Piece &a, const Piece &b) {
    double best = kInfinity;
    for (const Vec3 &v : a.vertices) best = std::min(best, point_piece_distance(v, b));
    for (const Vec3 &v : b.vertices) best = std::min(best, point_piece_distance(v, a));
    for (const Segment &e : a.edges)
        for (const Segment &f : b.edges) best = std::min(best, segment_segment_distance(e, f));
    for (const Segment &e : a.edges)
        for (const Triangle &t : b.faces) best = std::min(best, segment_triangle_distance(e, t));
    for (const Segment &e : b.edges)
        for (const Triangle &t : a.faces) best = std::min(best, segment_triangle_distance(e, t));
    return best;
}

double point_cylinder_distance(const Vec3 &p, const Cylinder &c) {
    const Vec3 local = c.axes.transpose() * (p - c.center);
    const double radial = std::max(0.0, std::hypot(local.x(), local.y()) - c.radius);
    const double axial = std::max(0.0, std::abs(local.z()) - 0.5 * c.length);
    return std::hypot(radial, axial);
}

}  // namespace oracle
