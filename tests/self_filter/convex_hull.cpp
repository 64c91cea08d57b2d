// An incremental convex hull (Clarkson and Shor's order-free variant, as in
// O'Rourke's "Computational Geometry in C"): each point outside the hull
// so far removes the faces it sees and joins the horizon's edges.
#include "surface_solid.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace filter_oracle {
namespace {

struct Face {
    std::array<size_t, 3> v;  // outward: counter-clockwise seen from outside
    Vec3 normal;
    double offset;
    bool alive = true;
};

class Hull {
public:
    explicit Hull(const std::vector<Vec3> &points) : p_(points) {}

    // Builds the first tetrahedron; returns its four points.
    std::array<size_t, 4> start(double eps);
    void add(size_t i, double eps);
    // The live faces over the original points (point i was original[order[i]]).
    std::vector<Triangle> triangles(const std::vector<Vec3> &original, const std::vector<size_t> &order) const;
    // Every original point lies within `tolerance` inside every face.
    void check(double tolerance, const std::vector<Vec3> &original) const;

private:
    void add_face(size_t a, size_t b, size_t c);
    double height(const Face &f, const Vec3 &x) const { return f.normal.dot(x) - f.offset; }

    const std::vector<Vec3> &p_;
    Vec3 inner_ = Vec3::Zero();  // a point inside the first tetrahedron, so inside every later hull
    std::vector<Face> faces_;
    std::map<std::pair<size_t, size_t>, size_t> edge_face_;  // directed edge -> its live face
};

void Hull::add_face(size_t a, size_t b, size_t c) {
    Face f;
    f.normal = (p_[b] - p_[a]).cross(p_[c] - p_[a]);
    if (f.normal.dot(inner_ - p_[a]) > 0.0) std::swap(b, c), f.normal = -f.normal;
    f.normal.normalize();
    f.offset = f.normal.dot(p_[a]);
    f.v = {a, b, c};
    for (int e = 0; e < 3; ++e) edge_face_[{f.v[e], f.v[(e + 1) % 3]}] = faces_.size();
    faces_.push_back(f);
}

// The first tetrahedron: extreme in x, farthest from it, from their line,
// from their plane.
std::array<size_t, 4> Hull::start(double eps) {
    const size_t n = p_.size();
    size_t a = 0, b = 0, c = 0, d = 0;
    for (size_t i = 0; i < n; ++i) if (p_[i].x() < p_[a].x()) a = i;
    for (size_t i = 0; i < n; ++i) if ((p_[i] - p_[a]).norm() > (p_[b] - p_[a]).norm()) b = i;
    const Vec3 axis = (p_[b] - p_[a]).normalized();
    const auto off_line = [&](size_t i) { return (p_[i] - p_[a]).cross(axis).norm(); };
    for (size_t i = 0; i < n; ++i) if (off_line(i) > off_line(c)) c = i;
    const Vec3 normal = (p_[b] - p_[a]).cross(p_[c] - p_[a]).normalized();
    const auto off_plane = [&](size_t i) { return std::fabs(normal.dot(p_[i] - p_[a])); };
    for (size_t i = 0; i < n; ++i) if (off_plane(i) > off_plane(d)) d = i;
    if (!(off_line(c) > eps) || !(off_plane(d) > eps)) throw std::runtime_error("convex_hull: a flat point set");
    inner_ = (p_[a] + p_[b] + p_[c] + p_[d]) / 4.0;
    add_face(a, b, c), add_face(a, b, d), add_face(a, c, d), add_face(b, c, d);
    return {a, b, c, d};
}

void Hull::add(size_t i, double eps) {
    std::vector<size_t> seen;
    for (size_t f = 0; f < faces_.size(); ++f)
        if (faces_[f].alive && height(faces_[f], p_[i]) > eps) seen.push_back(f);
    if (seen.empty()) return;
    for (size_t f : seen) faces_[f].alive = false;
    std::vector<std::pair<size_t, size_t>> horizon;
    for (size_t f : seen)
        for (int e = 0; e < 3; ++e) {
            const size_t from = faces_[f].v[e], to = faces_[f].v[(e + 1) % 3];
            edge_face_.erase({from, to});
            const auto across = edge_face_.find({to, from});
            if (across != edge_face_.end() && faces_[across->second].alive) horizon.push_back({from, to});
        }
    for (const auto &edge : horizon) add_face(edge.first, edge.second, i);
}

std::vector<Triangle> Hull::triangles(const std::vector<Vec3> &original, const std::vector<size_t> &order) const {
    std::vector<Triangle> out;
    for (const Face &f : faces_)
        if (f.alive) out.push_back(Triangle{original[order[f.v[0]]], original[order[f.v[1]]], original[order[f.v[2]]]});
    return out;
}

void Hull::check(double tolerance, const std::vector<Vec3> &original) const {
    for (const Face &f : faces_)
        if (f.alive)
            for (const Vec3 &x : original)
                if (height(f, x) > tolerance)
                    throw std::runtime_error("convex_hull: a point " + std::to_string(height(f, x)) +
                                             " m outside a face of the hull of " + std::to_string(p_.size()) +
                                             " points");
}

}  // namespace

// Meshes hold many coplanar points, where the visibility of nearly
// coplanar faces flips with rounding and the horizon splits.  The hull is
// built over the points each moved by at most kJitter (far below the
// oracle's 1e-8 m ambiguity), in general position, added in a random
// order; its faces are then given the original points.
constexpr double kJitter = 1e-10;

std::vector<Triangle> convex_hull(const std::vector<Vec3> &points) {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> jitter(-kJitter, kJitter);
    std::vector<size_t> order(points.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Vec3> moved;
    for (size_t i : order) moved.push_back(points[i] + Vec3(jitter(rng), jitter(rng), jitter(rng)));
    Hull hull(moved);
    const std::array<size_t, 4> first = hull.start(1e-9);
    // Heights below kVisible are rounding (the jitter puts points 1e-10
    // apart): such a point is taken as on the face, hence inside.
    constexpr double kVisible = 1e-14;
    for (size_t i = 0; i < moved.size(); ++i)
        if (std::find(first.begin(), first.end(), i) == first.end()) hull.add(i, kVisible);
    hull.check(1e-9, points);
    return hull.triangles(points, order);
}

bool is_closed(const std::vector<Triangle> &triangles) {
    const auto key = [](const Vec3 &v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
    std::map<std::pair<std::array<double, 3>, std::array<double, 3>>, int> edges;
    for (const Triangle &t : triangles) {
        const Vec3 *v[3] = {&t.a, &t.b, &t.c};
        for (int e = 0; e < 3; ++e) {
            auto a = key(*v[e]), b = key(*v[(e + 1) % 3]);
            if (b < a) std::swap(a, b);
            ++edges[{a, b}];
        }
    }
    for (const auto &edge : edges)
        if (edge.second != 2) return false;
    return true;
}

}  // namespace filter_oracle
