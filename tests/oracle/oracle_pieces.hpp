// Exact distances between two convex pieces of any kind (a point, a
// segment, a triangle, an oriented box, a solid polytope), for the
// self-collision oracle.  Independent of the library, textbook only:
//
//   distance(A, B) = min( each vertex of A vs the solid B, each vertex of B
//                         vs the solid A, every edge of A vs every edge of
//                         B, every edge of one vs every (triangulated) face
//                         of the other ).
//
// Disjoint: the closest points of two convex polytopes lie on a vertex-face
// or edge-edge pair, all of which are measured.  Intersecting: a vertex of
// their (convex, non-empty) intersection is a vertex of one inside the
// other, or where an edge of one crosses a face of the other (or, for
// segments and flat pieces, another edge): one of the terms is 0.
#pragma once

#include "oracle_fcl.hpp"
#include "oracle_geometry.hpp"

#include <vector>

namespace oracle {

struct Piece {
    // A cylinder is not a polytope: piece_distance does not take it (see
    // oracle_self's brackets); it is here for its bounds and its geometry.
    enum Kind { kPoint, kSegment, kTriangle, kBox, kPolytope, kCylinder };
    Kind kind = kPoint;
    std::vector<Vec3> vertices;
    std::vector<Segment> edges;
    std::vector<Triangle> faces;  // a polytope's or a box's triangulated faces
    OrientedBox box;              // kBox
    Polytope hull;                // kPolytope
    Cylinder cylinder;            // kCylinder
    Vec3 low = Vec3::Zero(), high = Vec3::Zero();  // bounds
};

Piece point_piece(const Vec3 &p);
Piece segment_piece(const Segment &s);
Piece triangle_piece(const Triangle &t);
Piece box_piece(const OrientedBox &box);
// Degenerate hulls (1 to 3 vertices) become points, segments, triangles.
Piece polytope_piece(const Polytope &hull);
Piece cylinder_piece(const Cylinder &cylinder);

// 0 inside a solid piece (a cylinder too).
double point_piece_distance(const Vec3 &p, const Piece &piece);
double segment_triangle_distance(const Segment &s, const Triangle &t);
// Two polytope pieces (no cylinder).
double piece_distance(const Piece &a, const Piece &b);
// The distance of the pieces' bounds: a lower bound of piece_distance.
double bounds_distance(const Piece &a, const Piece &b);

// The distance from p to a solid cylinder (0 inside), in closed form.
double point_cylinder_distance(const Vec3 &p, const Cylinder &cylinder);

}  // namespace oracle
