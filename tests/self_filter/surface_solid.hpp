// The oracle's solids bounded by triangles: a closed mesh (the solid it
// bounds, inside by the parity of a ray's crossings) and a convex hull of
// points (incremental hull, inside by its face planes).  Distances are
// exact point-to-triangle minima (oracle_geometry.hpp, Ericson) over a
// median-split box tree whose boxes only prune (exact lower bounds).
// Independent of the library: nothing here is read from it but the
// triangles and vertices its public API returns.
#pragma once

#include "oracle_geometry.hpp"

#include <array>
#include <cmath>
#include <vector>

namespace filter_oracle {

using oracle::Triangle;
using oracle::Vec3;

// The faces of the convex hull of `points` as triangles, outward; throws
// std::runtime_error for a flat set.  Every point lies within 1e-9 m
// inside every face's plane (checked).
std::vector<Triangle> convex_hull(const std::vector<Vec3> &points);

// Whether every edge of the triangles (vertices equal by coordinates) is
// shared by exactly two of them.
bool is_closed(const std::vector<Triangle> &triangles);

class SurfaceSolid {
public:
    // A closed mesh's solid (`convex` false) or a convex hull (`convex`
    // true: the triangles are its faces, outward).
    SurfaceSolid(std::vector<Triangle> triangles, bool convex);

    // The distance from x to the solid: 0 inside, else to the nearest
    // triangle.
    double distance(const Vec3 &x) const { return distance_below(x, INFINITY); }
    // The same when it is below `limit`; else some value >= limit.
    double distance_below(const Vec3 &x, double limit) const;
    // A lower bound of the distance: to the triangles' bounding box.
    double box_gap(const Vec3 &x) const;
    const std::vector<Triangle> &triangles() const { return triangles_; }
    const Vec3 &box_min() const { return nodes_[0].lo; }
    const Vec3 &box_max() const { return nodes_[0].hi; }

private:
    struct Node {
        Vec3 lo, hi;
        int left = -1, right = -1;  // children, or -1 in a leaf
        size_t first = 0, count = 0;  // a leaf's triangles
    };
    int build(size_t first, size_t count);
    void nearest(int node, const Vec3 &x, double &best) const;
    bool inside(const Vec3 &x) const;
    bool parity_inside(const Vec3 &x) const;

    std::vector<Triangle> triangles_;
    std::vector<Node> nodes_;
    bool convex_;
    std::vector<std::array<double, 4>> planes_;  // convex: outward normal, offset
};

}  // namespace filter_oracle
