// Exact brute-force distances between an axis-aligned cell (a cube) and the
// convex pieces robot shapes are made of.  Independent of the library: only
// textbook algorithms (Ericson, "Real-Time Collision Detection"; Akenine-Moller's
// triangle-box test; Gottschalk's separating axes), written for clarity, not
// speed.
//
// Every pair is a pair of convex polytopes (a point, a segment, a triangle,
// an oriented box, a solid hull) and a cube.  Their distance is
//   0                                 when they intersect (separating axes), else
//   min( each vertex of one vs the other solid, every edge vs every edge ),
// which is exact: the closest points of two disjoint convex polytopes lie on
// a vertex-face, vertex-edge, vertex-vertex or edge-edge pair.
//
// Cylinders are curved: oracle_fcl.hpp measures them with FCL.
#pragma once

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace oracle {

using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// An axis-aligned cube: an octree cell.
struct Cell {
    Vec3 center = Vec3::Zero();
    double half = 0.0;  // half of the edge
};

struct Segment {
    Vec3 a = Vec3::Zero(), b = Vec3::Zero();
};

struct Triangle {
    Vec3 a = Vec3::Zero(), b = Vec3::Zero(), c = Vec3::Zero();
};

struct OrientedBox {
    Vec3 center = Vec3::Zero();
    Mat3 axes = Mat3::Identity();  // columns: the box's x, y, z in the map frame
    Vec3 half = Vec3::Zero();      // half edges
};

// A solid convex polytope given with ALL its faces as triangles (any
// winding); its vertices are exactly the hull's extreme points.  At least a
// tetrahedron: lower-dimensional hulls are points, segments or triangles.
struct Polytope {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> faces;
};

// ---- distances cell vs piece ------------------------------------------
double point_cell_distance(const Vec3 &p, const Cell &cell);
double segment_cell_distance(const Segment &s, const Cell &cell);
double triangle_cell_distance(const Triangle &t, const Cell &cell);
double box_cell_distance(const OrientedBox &box, const Cell &cell);
double polytope_cell_distance(const Polytope &hull, const Cell &cell);

// ---- building blocks (exposed for the oracle's own sanity test) --------
Vec3 closest_point_on_segment(const Vec3 &p, const Segment &s);
Vec3 closest_point_on_triangle(const Vec3 &p, const Triangle &t);  // Ericson 5.1.5
double point_triangle_distance(const Vec3 &p, const Triangle &t);  // degenerate ones too
double segment_segment_distance(const Segment &s1, const Segment &s2);  // Ericson 5.1.9
double point_box_distance(const Vec3 &p, const OrientedBox &box);
double point_polytope_distance(const Vec3 &p, const Polytope &hull);  // 0 inside

std::array<Vec3, 8> cell_corners(const Cell &cell);
std::array<Segment, 12> cell_edges(const Cell &cell);
std::array<Vec3, 8> box_corners(const OrientedBox &box);
std::vector<Segment> polytope_edges(const Polytope &hull);  // each edge once

}  // namespace oracle
