#include "geometry/simplex.hpp"

#include <cmath>

namespace octoprox {
namespace {

// A candidate closest point: which of the current vertices carry it.
struct Feature {
    int index[3] = {0, 0, 0};
    double weight[3] = {0, 0, 0};
    int count = 0;
    double distance2 = 0.0;
};

Feature point_feature(const Vec3 *w, int a) {
    Feature f;
    f.index[0] = a, f.weight[0] = 1.0, f.count = 1;
    f.distance2 = w[a].squaredNorm();
    return f;
}

Feature segment_feature(const Vec3 *w, int a, int b) {
    const Vec3 ab = w[b] - w[a];
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0.0 ? -w[a].dot(ab) / length2 : 0.0;
    if (t <= 0.0) return point_feature(w, a);
    if (t >= 1.0) return point_feature(w, b);
    Feature f;
    f.index[0] = a, f.index[1] = b;
    f.weight[0] = 1.0 - t, f.weight[1] = t, f.count = 2;
    f.distance2 = (w[a] + t * ab).squaredNorm();
    return f;
}

Feature best_of(const Feature &x, const Feature &y) { return y.distance2 < x.distance2 ? y : x; }

// Closest point of triangle (a, b, c) to the origin, by its Voronoi regions.
Feature triangle_feature(const Vec3 *w, int ia, int ib, int ic) {
    const Vec3 &a = w[ia], &b = w[ib], &c = w[ic];
    const Vec3 ab = b - a, ac = c - a;
    const double d1 = -ab.dot(a), d2 = -ac.dot(a);
    if (d1 <= 0 && d2 <= 0) return point_feature(w, ia);
    const double d3 = -ab.dot(b), d4 = -ac.dot(b);
    if (d3 >= 0 && d4 <= d3) return point_feature(w, ib);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return segment_feature(w, ia, ib);
    const double d5 = -ab.dot(c), d6 = -ac.dot(c);
    if (d6 >= 0 && d5 <= d6) return point_feature(w, ic);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return segment_feature(w, ia, ic);
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return segment_feature(w, ib, ic);
    const double sum = va + vb + vc;
    // A degenerate (flat) triangle: its closest point lies on an edge.
    if (!(std::fabs(sum) > 0.0))
        return best_of(best_of(segment_feature(w, ia, ib), segment_feature(w, ia, ic)),
                       segment_feature(w, ib, ic));
    Feature f;
    f.index[0] = ia, f.index[1] = ib, f.index[2] = ic, f.count = 3;
    f.weight[1] = vb / sum, f.weight[2] = vc / sum, f.weight[0] = 1.0 - f.weight[1] - f.weight[2];
    f.distance2 = (a + f.weight[1] * ab + f.weight[2] * ac).squaredNorm();
    return f;
}

// Is the origin on the other side of plane (a, b, c) than vertex d?  A flat
// tetrahedron counts as "outside" everywhere, so its faces are all tried.
bool origin_outside_face(const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d) {
    const Vec3 normal = (b - a).cross(c - a);
    const double side_origin = -a.dot(normal);
    const double side_d = (d - a).dot(normal);
    const double scale = normal.norm() * ((d - a).norm() + 1e-300);
    if (std::fabs(side_d) <= 1e-12 * scale) return true;
    return side_origin * side_d <= 0.0;
}

}  // namespace

bool Simplex::reduce_to_closest() {
    Feature f;
    if (size == 1) f = point_feature(w, 0);
    else if (size == 2) f = segment_feature(w, 0, 1);
    else if (size == 3) f = triangle_feature(w, 0, 1, 2);
    else {
        static const int faces[4][4] = {{0, 1, 2, 3}, {0, 2, 3, 1}, {0, 3, 1, 2}, {1, 3, 2, 0}};
        bool found = false;
        for (const auto &face : faces) {
            if (!origin_outside_face(w[face[0]], w[face[1]], w[face[2]], w[face[3]])) continue;
            const Feature candidate = triangle_feature(w, face[0], face[1], face[2]);
            f = found ? best_of(f, candidate) : candidate;
            found = true;
        }
        if (!found) return false;  // origin inside: the shapes intersect
    }
    Vec3 kept_w[3], kept_s[3], kept_c[3];
    for (int i = 0; i < f.count; ++i) {
        const int k = f.index[i];
        kept_w[i] = w[k], kept_s[i] = s[k], kept_c[i] = c[k];
    }
    for (int i = 0; i < f.count; ++i) {
        w[i] = kept_w[i], s[i] = kept_s[i], c[i] = kept_c[i];
        bary[i] = f.weight[i];
    }
    size = f.count;
    return true;
}

Vec3 Simplex::closest() const {
    Vec3 p = Vec3::Zero();
    for (int i = 0; i < size; ++i) p += bary[i] * w[i];
    return p;
}

}  // namespace octoprox
