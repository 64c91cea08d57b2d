#include "oracle_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <set>
#include <utility>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

using PointDistance = std::function<double(const Vec3 &)>;

// ---- separating axes ----------------------------------------------------

// Does `axis` separate the convex hull of `vertices` from the cell?  Closed
// sets: intervals that share an end point are NOT separated (touching is
// intersecting).
bool axis_separates(const Vec3 &axis, const std::vector<Vec3> &vertices, const Cell &cell) {
    double low = kInfinity, high = -kInfinity;
    for (const Vec3 &v : vertices) {
        const double projection = axis.dot(v);
        low = std::min(low, projection);
        high = std::max(high, projection);
    }
    const double cell_middle = axis.dot(cell.center);
    const double cell_radius = cell.half * axis.cwiseAbs().sum();
    return high < cell_middle - cell_radius || low > cell_middle + cell_radius;
}

// Candidate axes of a convex piece vs a cube: the cube's three face normals,
// the piece's face normals, and every (piece edge) x (cube edge) cross
// product.  Parallel pairs give a zero vector and are skipped: such a plane
// is already covered by a face normal (the Minkowski difference of the two
// has no face there).
bool intersects_cell(const std::vector<Vec3> &vertices, const std::vector<Vec3> &face_normals,
                     const std::vector<Vec3> &edge_directions, const Cell &cell) {
    std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ()};
    axes.insert(axes.end(), face_normals.begin(), face_normals.end());
    for (const Vec3 &edge : edge_directions)
        for (int k = 0; k < 3; ++k) axes.push_back(edge.cross(Vec3::Unit(k)));
    for (const Vec3 &axis : axes) {
        if (axis.squaredNorm() < 1e-24) continue;
        if (axis_separates(axis, vertices, cell)) return false;
    }
    return true;
}

// ---- feature pairs --------------------------------------------------------

// The distance of two DISJOINT convex polytopes: vertex of one vs the other
// solid, both ways, and every edge pair.
double feature_distance(const std::vector<Vec3> &vertices, const std::vector<Segment> &edges,
                        const PointDistance &point_to_piece, const Cell &cell) {
    double best = kInfinity;
    for (const Vec3 &v : vertices) best = std::min(best, point_cell_distance(v, cell));
    for (const Vec3 &corner : cell_corners(cell)) best = std::min(best, point_to_piece(corner));
    for (const Segment &edge : edges)
        for (const Segment &cell_edge : cell_edges(cell))
            best = std::min(best, segment_segment_distance(edge, cell_edge));
    return best;
}

std::vector<Vec3> directions_of(const std::vector<Segment> &edges) {
    std::vector<Vec3> directions;
    for (const Segment &e : edges) directions.push_back(e.b - e.a);
    return directions;
}

Vec3 face_normal(const Vec3 &a, const Vec3 &b, const Vec3 &c) { return (b - a).cross(c - a); }

}  // namespace

// ---- simple features --------------------------------------------------------

std::array<Vec3, 8> cell_corners(const Cell &cell) {
    OrientedBox box;
    box.center = cell.center;
    box.half = Vec3::Constant(cell.half);
    return box_corners(box);
}

std::array<Vec3, 8> box_corners(const OrientedBox &box) {
    std::array<Vec3, 8> corners;
    for (int i = 0; i < 8; ++i) {
        Vec3 local;
        for (int k = 0; k < 3; ++k) local[k] = ((i >> k) & 1) ? box.half[k] : -box.half[k];
        corners[i] = box.center + box.axes * local;
    }
    return corners;
}

// The 12 edges join corners whose indices differ in one bit.
static std::vector<Segment> box_edges(const std::array<Vec3, 8> &corners) {
    std::vector<Segment> edges;
    for (int i = 0; i < 8; ++i)
        for (int k = 0; k < 3; ++k)
            if (!((i >> k) & 1)) edges.push_back({corners[i], corners[i | (1 << k)]});
    return edges;
}

std::array<Segment, 12> cell_edges(const Cell &cell) {
    const std::vector<Segment> edges = box_edges(cell_corners(cell));
    std::array<Segment, 12> out;
    std::copy(edges.begin(), edges.end(), out.begin());
    return out;
}

std::vector<Segment> polytope_edges(const Polytope &hull) {
    std::set<std::pair<int, int>> unique;
    for (const auto &f : hull.faces)
        for (int k = 0; k < 3; ++k) {
            const int i = f[k], j = f[(k + 1) % 3];
            unique.insert({std::min(i, j), std::max(i, j)});
        }
    std::vector<Segment> edges;
    for (const auto &[i, j] : unique) edges.push_back({hull.vertices[i], hull.vertices[j]});
    return edges;
}

// ---- point queries ------------------------------------------------------------

double point_cell_distance(const Vec3 &p, const Cell &cell) {
    return ((p - cell.center).cwiseAbs() - Vec3::Constant(cell.half)).cwiseMax(0.0).norm();
}

double point_box_distance(const Vec3 &p, const OrientedBox &box) {
    const Vec3 local = box.axes.transpose() * (p - box.center);
    return (local.cwiseAbs() - box.half).cwiseMax(0.0).norm();
}

Vec3 closest_point_on_segment(const Vec3 &p, const Segment &s) {
    const Vec3 ab = s.b - s.a;
    const double length2 = ab.squaredNorm();
    if (length2 == 0.0) return s.a;
    const double t = std::clamp((p - s.a).dot(ab) / length2, 0.0, 1.0);
    return s.a + t * ab;
}

// Ericson 5.1.5: find the Voronoi region of p among the triangle's features.
Vec3 closest_point_on_triangle(const Vec3 &p, const Triangle &t) {
    const Vec3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0.0 && d2 <= 0.0) return t.a;
    const Vec3 bp = p - t.b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0.0 && d4 <= d3) return t.b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return t.a + (d1 / (d1 - d3)) * ab;
    const Vec3 cp = p - t.c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0.0 && d5 <= d6) return t.c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return t.a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
        return t.b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (t.c - t.b);
    const double denominator = 1.0 / (va + vb + vc);
    return t.a + ab * (vb * denominator) + ac * (vc * denominator);
}

double point_triangle_distance(const Vec3 &p, const Triangle &t) {
    // A degenerate triangle (a segment or a point) is the union of its edges;
    // Ericson's barycentric formula would divide by zero there.
    if ((t.b - t.a).cross(t.c - t.a).squaredNorm() == 0.0) {
        double best = kInfinity;
        for (const Segment &edge : {Segment{t.a, t.b}, Segment{t.b, t.c}, Segment{t.c, t.a}})
            best = std::min(best, (p - closest_point_on_segment(p, edge)).norm());
        return best;
    }
    return (p - closest_point_on_triangle(p, t)).norm();
}

double point_polytope_distance(const Vec3 &p, const Polytope &hull) {
    Vec3 centroid = Vec3::Zero();
    for (const Vec3 &v : hull.vertices) centroid += v;
    centroid /= double(hull.vertices.size());
    bool inside = true;
    double best = kInfinity;
    for (const auto &f : hull.faces) {
        const Triangle t{hull.vertices[f[0]], hull.vertices[f[1]], hull.vertices[f[2]]};
        Vec3 normal = face_normal(t.a, t.b, t.c);
        if (normal.dot(centroid - t.a) > 0.0) normal = -normal;  // outward
        if (normal.dot(p - t.a) > 0.0) inside = false;
        best = std::min(best, point_triangle_distance(p, t));
    }
    return inside ? 0.0 : best;
}

// Ericson 5.1.9, with his degenerate cases (a segment reduced to a point).
double segment_segment_distance(const Segment &s1, const Segment &s2) {
    const Vec3 d1 = s1.b - s1.a, d2 = s2.b - s2.a, r = s1.a - s2.a;
    const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
    double s = 0.0, t = 0.0;
    if (a == 0.0 && e == 0.0) return r.norm();
    if (a == 0.0) {
        t = std::clamp(f / e, 0.0, 1.0);
    } else {
        const double c = d1.dot(r);
        if (e == 0.0) {
            s = std::clamp(-c / a, 0.0, 1.0);
        } else {
            const double b = d1.dot(d2), denominator = a * e - b * b;
            // Parallel segments (denominator 0): any s works; take 0.
            s = denominator != 0.0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
            t = (b * s + f) / e;
            if (t < 0.0) {
                t = 0.0;
                s = std::clamp(-c / a, 0.0, 1.0);
            } else if (t > 1.0) {
                t = 1.0;
                s = std::clamp((b - c) / a, 0.0, 1.0);
            }
        }
    }
    return ((s1.a + s * d1) - (s2.a + t * d2)).norm();
}

// ---- cell vs piece -------------------------------------------------------------

double segment_cell_distance(const Segment &seg, const Cell &cell) {
    const std::vector<Vec3> vertices = {seg.a, seg.b};
    const std::vector<Segment> edges = {seg};
    // Slab test as separating axes: cube normals and segment x cube edges.
    if (intersects_cell(vertices, {}, directions_of(edges), cell)) return 0.0;
    return feature_distance(vertices, edges,
                            [&](const Vec3 &p) { return (p - closest_point_on_segment(p, seg)).norm(); },
                            cell);
}

double triangle_cell_distance(const Triangle &t, const Cell &cell) {
    const std::vector<Vec3> vertices = {t.a, t.b, t.c};
    const std::vector<Segment> edges = {{t.a, t.b}, {t.b, t.c}, {t.c, t.a}};
    // Akenine-Moller's 13 axes.
    if (intersects_cell(vertices, {face_normal(t.a, t.b, t.c)}, directions_of(edges), cell)) return 0.0;
    return feature_distance(vertices, edges, [&](const Vec3 &p) { return point_triangle_distance(p, t); }, cell);
}

double box_cell_distance(const OrientedBox &box, const Cell &cell) {
    const std::array<Vec3, 8> corners = box_corners(box);
    const std::vector<Vec3> vertices(corners.begin(), corners.end());
    const std::vector<Segment> edges = box_edges(corners);
    // 15 axes: 3 + 3 face normals and 9 edge cross products.
    const std::vector<Vec3> normals = {box.axes.col(0), box.axes.col(1), box.axes.col(2)};
    if (intersects_cell(vertices, normals, normals, cell)) return 0.0;
    return feature_distance(vertices, edges, [&](const Vec3 &p) { return point_box_distance(p, box); },
                            cell);
}

double polytope_cell_distance(const Polytope &hull, const Cell &cell) {
    const std::vector<Segment> edges = polytope_edges(hull);
    std::vector<Vec3> normals;
    for (const auto &f : hull.faces)
        normals.push_back(face_normal(hull.vertices[f[0]], hull.vertices[f[1]], hull.vertices[f[2]]));
    if (intersects_cell(hull.vertices, normals, directions_of(edges), cell)) return 0.0;
    return feature_distance(hull.vertices, edges,
                            [&](const Vec3 &p) { return point_polytope_distance(p, hull); }, cell);
}

}  // namespace oracle
