#include "geometry/convex_hull.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace octoprox {
namespace {

// Of the set's size: points this near a face's plane are on it.
constexpr double kCoplanar = 1e-12;
// The result holds every point to within this many tolerances.
constexpr double kCheckSlack = 16.0;

struct Face {
    std::array<uint32_t, 3> v;
    Vec3 normal;  // unit, outward
    double offset;
};

Face make_face(const std::vector<Vec3> &p, uint32_t a, uint32_t b, uint32_t c) {
    Face face{{a, b, c}, (p[b] - p[a]).cross(p[c] - p[a]), 0.0};
    const double length = face.normal.norm();
    if (length > 0.0) face.normal /= length;
    face.offset = face.normal.dot(p[a]);
    return face;
}

uint64_t directed(uint32_t a, uint32_t b) { return (uint64_t{a} << 32) | b; }

// The starting tetrahedron's corners, widest first; false when flat.
bool start_corners(const std::vector<Vec3> &p, double tolerance, std::array<uint32_t, 4> &corner) {
    corner = {0, 0, 0, 0};
    for (uint32_t i = 1; i < p.size(); ++i)
        if (p[i].x() < p[corner[0]].x()) corner[0] = i;
    double best = 0.0;
    for (uint32_t i = 0; i < p.size(); ++i)
        if ((p[i] - p[corner[0]]).squaredNorm() > best) best = (p[i] - p[corner[0]]).squaredNorm(), corner[1] = i;
    const Vec3 axis = (p[corner[1]] - p[corner[0]]).normalized();
    best = 0.0;
    for (uint32_t i = 0; i < p.size(); ++i) {
        const double off = (p[i] - p[corner[0]]).cross(axis).norm();
        if (off > best) best = off, corner[2] = i;
    }
    if (!(best > tolerance)) return false;
    const Vec3 normal = (p[corner[1]] - p[corner[0]]).cross(p[corner[2]] - p[corner[0]]).normalized();
    best = 0.0;
    for (uint32_t i = 0; i < p.size(); ++i) {
        const double height = std::fabs(normal.dot(p[i] - p[corner[0]]));
        if (height > best) best = height, corner[3] = i;
    }
    return best > tolerance;
}

// Replaces the faces `point` sees by a fan from it to their horizon.
void add_point(const std::vector<Vec3> &p, uint32_t point, double tolerance, std::vector<Face> &faces) {
    std::vector<Face> kept;
    std::unordered_set<uint64_t> seen_edges;
    std::vector<uint64_t> edges;
    for (const Face &face : faces) {
        if (face.normal.dot(p[point]) - face.offset > tolerance) {
            for (int k = 0; k < 3; ++k) {
                seen_edges.insert(directed(face.v[k], face.v[(k + 1) % 3]));
                edges.push_back(directed(face.v[k], face.v[(k + 1) % 3]));
            }
        } else {
            kept.push_back(face);
        }
    }
    if (edges.empty()) return;  // inside, or on the hull
    for (const uint64_t edge : edges) {
        const uint32_t a = uint32_t(edge >> 32), b = uint32_t(edge);
        if (seen_edges.count(directed(b, a)) == 0) kept.push_back(make_face(p, a, b, point));
    }
    faces.swap(kept);
}

bool holds_all(const std::vector<Vec3> &p, const std::vector<Face> &faces, double tolerance) {
    for (const Face &face : faces) {
        if (face.normal == Vec3::Zero()) return false;
        for (const Vec3 &x : p)
            if (face.normal.dot(x) - face.offset > kCheckSlack * tolerance) return false;
    }
    return true;
}

// Every directed edge once, its reverse once: a closed, oriented surface.
bool closed_and_oriented(const std::vector<Face> &faces) {
    std::vector<uint64_t> edges;
    for (const Face &face : faces)
        for (int k = 0; k < 3; ++k) edges.push_back(directed(face.v[k], face.v[(k + 1) % 3]));
    std::sort(edges.begin(), edges.end());
    if (std::adjacent_find(edges.begin(), edges.end()) != edges.end()) return false;
    for (const uint64_t e : edges)
        if (!std::binary_search(edges.begin(), edges.end(), (e << 32) | (e >> 32))) return false;
    return true;
}

}  // namespace

bool convex_hull(const std::vector<Vec3> &points, HullMesh &hull) {
    hull = HullMesh();
    if (points.size() < 4) return false;
    Vec3 lo = points[0], hi = points[0];
    for (const Vec3 &x : points) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    const double tolerance = kCoplanar * std::max((hi - lo).norm(), hi.cwiseAbs().maxCoeff() + lo.cwiseAbs().maxCoeff());
    std::array<uint32_t, 4> c;
    if (!start_corners(points, tolerance, c)) return false;
    // Outward: the fourth corner below the first face.
    Face first = make_face(points, c[0], c[1], c[2]);
    if (first.normal.dot(points[c[3]]) > first.offset) std::swap(c[1], c[2]);
    std::vector<Face> faces = {make_face(points, c[0], c[1], c[2]), make_face(points, c[0], c[3], c[1]),
                               make_face(points, c[1], c[3], c[2]), make_face(points, c[2], c[3], c[0])};
    for (uint32_t i = 0; i < points.size(); ++i) add_point(points, i, tolerance, faces);
    if (!closed_and_oriented(faces) || !holds_all(points, faces, tolerance)) return false;
    // Only the vertices the faces use, renumbered.
    std::vector<int64_t> index(points.size(), -1);
    for (const Face &face : faces) {
        std::array<uint32_t, 3> t;
        for (int k = 0; k < 3; ++k) {
            if (index[face.v[k]] < 0) index[face.v[k]] = int64_t(hull.vertices.size()), hull.vertices.push_back(points[face.v[k]]);
            t[k] = uint32_t(index[face.v[k]]);
        }
        hull.triangles.push_back(t);
    }
    return true;
}

}  // namespace octoprox
