// The penetration oracle: how deep a padded shape is in ONE cell (the
// semantics of opx_contact.depth and of signed distances, query.h).
//
// The core of every shape but the cylinder is a convex polytope (a point, a
// segment, a triangle, an oriented box, a hull).  Its penetration depth into
// a cell (the shortest translation that separates them) is found by the
// separating-axis test: the minimum overlap over every candidate axis, the
// cell's three face normals, the core's face normals and every cross product
// of a core edge with a cell edge.  These include every face normal of the
// Minkowski difference of the two polytopes, where the minimum lies, so the
// answer is exact (and the minimising axis is a separating direction).
//
// A padded shape adds its ball: depth = core depth + inflation when the
// cores overlap, else inflation - core distance (only the ball reaches in).
// A mesh is its triangles: the depth of its deepest triangle.
//
// Cylinders are curved: their depth is bracketed exactly instead, between
// the depths of an inscribed and a circumscribed prism (depth grows with the
// shape: a translation separating the larger prism separates the cylinder).
#pragma once

#include "oracle_robot.hpp"

#include <vector>

namespace oracle {

// A convex core as the separating-axis test needs it.
struct ConvexCore {
    std::vector<Vec3> vertices;
    std::vector<Vec3> face_normals;     // any length, any sign; zero ones are skipped
    std::vector<Vec3> edge_directions;  // any length; zero ones are skipped
};

// The core's overlap with the cell along its best axis: > 0 deep, 0 touching,
// < 0 separated (then only the sign is meaningful).  `normal` gets the
// direction the core went in: moving it by -overlap * normal separates them.
double sat_overlap(const ConvexCore &core, const Cell &cell, Vec3 &normal);

struct DepthAnswer {
    bool exact = false;         // false for cylinders: only low <= depth <= high
    bool core_overlaps = false; // the core itself reaches into the cell
    double depth = 0.0;         // padding included, clamped at 0
    double low = 0.0, high = 0.0;  // bounds of the depth (both `depth` when exact)
    Vec3 normal = Vec3::Zero(); // when core_overlaps: a direction achieving depth
};

// The padded shape's depth in the cell.  A mesh: its deepest triangle.  A
// cylinder: bracketed by prisms of `prism_sides` sides (depth = the middle).
DepthAnswer padded_depth(const PlacedShape &shape, const Cell &cell, int prism_sides = 64);

// The core's distance to the cell (0 when they overlap).  Cylinders by FCL
// (oracle_fcl.hpp): -1 or 0 when overlapping.
double core_cell_distance(const PlacedShape &shape, const Cell &cell);

// Distance from a point to the shape's core (0 inside a solid core).
double core_point_distance(const PlacedShape &shape, const Vec3 &point);

// The same shape moved by `offset` (map frame).
PlacedShape translated(const PlacedShape &shape, const Vec3 &offset);

}  // namespace oracle
