// The closest point to the origin of a simplex of 1 to 4 points (the inner
// step of GJK), by Voronoi regions.  Keeps only the vertices that support
// the closest point, with their barycentric weights.
#pragma once

#include "geometry/pose.hpp"

namespace octoprox {

struct Simplex {
    Vec3 w[4];      // points of the Minkowski difference (shape - cell)
    Vec3 s[4];      // the shape's support points behind them
    Vec3 c[4];      // the cell's support points behind them
    double bary[4]; // barycentric weights of the closest point
    int size = 0;

    void push(const Vec3 &wi, const Vec3 &si, const Vec3 &ci) {
        w[size] = wi, s[size] = si, c[size] = ci, bary[size] = 0.0;
        ++size;
    }
    // Reduces to the closest feature; returns false when the origin lies
    // inside the tetrahedron (the shapes intersect).
    bool reduce_to_closest();
    Vec3 closest() const;
};

}  // namespace octoprox
