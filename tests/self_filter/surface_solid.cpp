#include "surface_solid.hpp"

#include <algorithm>
#include <cmath>

namespace filter_oracle {
namespace {

constexpr size_t kLeafTriangles = 4;
// Twice the area (m^2) below which a hull face is a sliver of collinear
// points (the hull is built over jittered points, convex_hull).
constexpr double kSliver = 1e-13;

Vec3 centroid(const Triangle &t) { return (t.a + t.b + t.c) / 3.0; }

double box_distance(const Vec3 &lo, const Vec3 &hi, const Vec3 &x) {
    return (lo - x).cwiseMax(x - hi).cwiseMax(0.0).norm();
}

// Whether the ray x + t dir, t >= 0, meets the box.
bool ray_meets_box(const Vec3 &lo, const Vec3 &hi, const Vec3 &x, const Vec3 &dir) {
    double t0 = 0.0, t1 = INFINITY;
    for (int a = 0; a < 3; ++a) {
        const double u = (lo[a] - x[a]) / dir[a], v = (hi[a] - x[a]) / dir[a];
        t0 = std::max(t0, std::min(u, v)), t1 = std::min(t1, std::max(u, v));
    }
    return t0 <= t1;
}

// Möller and Trumbore: 1 for a crossing at t > 0, 0 for none, -1 when the
// ray passes too near an edge or the start lies too near the plane to tell.
int crossing(const Triangle &tri, const Vec3 &x, const Vec3 &dir) {
    constexpr double kNear = 1e-9;
    const Vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
    const Vec3 p = dir.cross(e2);
    const double det = e1.dot(p);
    if (std::fabs(det) <= kNear * e1.norm() * e2.norm()) return 0;  // parallel: not crossed
    const Vec3 s = x - tri.a, q = s.cross(e1);
    const double u = s.dot(p) / det, v = dir.dot(q) / det, t = e2.dot(q) / det;
    if (u < -kNear || v < -kNear || u + v > 1.0 + kNear || t < -kNear) return 0;
    if (u < kNear || v < kNear || u + v > 1.0 - kNear || t < kNear) return -1;
    return 1;
}

}  // namespace

SurfaceSolid::SurfaceSolid(std::vector<Triangle> triangles, bool convex)
    : triangles_(std::move(triangles)), convex_(convex) {
    build(0, triangles_.size());
    if (!convex_) return;
    for (const Triangle &t : triangles_) {
        const Vec3 cross = (t.b - t.a).cross(t.c - t.a);
        if (!(cross.norm() > kSliver)) continue;  // collinear corners: no plane (its edges are other faces')
        const Vec3 n = cross.normalized();
        planes_.push_back({n.x(), n.y(), n.z(), n.dot(t.a)});
    }
}

int SurfaceSolid::build(size_t first, size_t count) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Vec3 lo = Vec3::Constant(INFINITY), hi = Vec3::Constant(-INFINITY);
    for (size_t i = first; i < first + count; ++i)
        for (const Vec3 *v : {&triangles_[i].a, &triangles_[i].b, &triangles_[i].c})
            lo = lo.cwiseMin(*v), hi = hi.cwiseMax(*v);
    nodes_[index].lo = lo, nodes_[index].hi = hi;
    if (count <= kLeafTriangles) {
        nodes_[index].first = first, nodes_[index].count = count;
        return index;
    }
    int axis = 0;
    (hi - lo).maxCoeff(&axis);
    const auto begin = triangles_.begin() + static_cast<std::ptrdiff_t>(first);
    std::nth_element(begin, begin + static_cast<std::ptrdiff_t>(count / 2), begin + static_cast<std::ptrdiff_t>(count),
                     [axis](const Triangle &a, const Triangle &b) { return centroid(a)[axis] < centroid(b)[axis]; });
    const int left = build(first, count / 2);
    const int right = build(first + count / 2, count - count / 2);
    nodes_[index].left = left, nodes_[index].right = right;
    return index;
}

void SurfaceSolid::nearest(int index, const Vec3 &x, double &best) const {
    const Node &node = nodes_[index];
    if (box_distance(node.lo, node.hi, x) >= best) return;
    if (node.left < 0) {
        for (size_t i = node.first; i < node.first + node.count; ++i)
            best = std::min(best, oracle::point_triangle_distance(x, triangles_[i]));
        return;
    }
    const double dl = box_distance(nodes_[node.left].lo, nodes_[node.left].hi, x);
    const double dr = box_distance(nodes_[node.right].lo, nodes_[node.right].hi, x);
    const int near = dl <= dr ? node.left : node.right, far = dl <= dr ? node.right : node.left;
    nearest(near, x, best);
    nearest(far, x, best);
}

bool SurfaceSolid::parity_inside(const Vec3 &x) const {
    static const Vec3 kDirections[] = {Vec3(0.48, 0.61, 0.63), Vec3(-0.71, 0.23, 0.66), Vec3(0.17, -0.88, 0.44),
                                       Vec3(-0.39, -0.52, -0.76), Vec3(0.83, -0.31, -0.46)};
    for (const Vec3 &dir : kDirections) {
        int crossings = 0;
        bool clear = true;
        std::vector<int> stack = {0};
        while (!stack.empty() && clear) {
            const Node &node = nodes_[stack.back()];
            stack.pop_back();
            if (!ray_meets_box(node.lo, node.hi, x, dir)) continue;
            if (node.left >= 0) {
                stack.push_back(node.left), stack.push_back(node.right);
                continue;
            }
            for (size_t i = node.first; i < node.first + node.count && clear; ++i) {
                const int c = crossing(triangles_[i], x, dir);
                clear = c >= 0, crossings += c;
            }
        }
        if (clear) return crossings % 2 == 1;
    }
    return false;  // every direction grazed an edge: only on the surface, where the distance is ~0 anyway
}

bool SurfaceSolid::inside(const Vec3 &x) const {
    if (box_distance(box_min(), box_max(), x) > 0.0) return false;
    if (!convex_) return parity_inside(x);
    for (const auto &p : planes_)
        if (p[0] * x.x() + p[1] * x.y() + p[2] * x.z() > p[3]) return false;
    return true;
}

double SurfaceSolid::distance_below(const Vec3 &x, double limit) const {
    double best = limit;
    nearest(0, x, best);
    return inside(x) ? 0.0 : best;
}

double SurfaceSolid::box_gap(const Vec3 &x) const { return box_distance(box_min(), box_max(), x); }

}  // namespace filter_oracle
