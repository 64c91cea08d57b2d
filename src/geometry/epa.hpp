// Penetration depth of a convex piece into a cell box (or into another
// convex piece), by the expanding polytope algorithm (EPA) on their
// Minkowski difference, started from the tetrahedron GJK ends with.
// Between polytopes it ends on the exact face of the difference; for
// cylinders to GJK's tolerance.  Fixed-size arrays: no heap allocation.
#pragma once

#include "geometry/convex.hpp"
#include "geometry/simplex.hpp"

namespace octoprox {

struct Penetration {
    double depth = 0.0;
    Vec3 normal = Vec3::UnitX();   // the direction the piece went into the cell:
                                   // moving it by -depth * normal separates them
    Vec3 on_shape = Vec3::Zero();  // the piece's point deepest in the cell
    Vec3 on_cell = Vec3::Zero();   // where it leaves the cell along -normal
};

// `start` is GJK's simplex on intersection (a tetrahedron around the
// origin); a smaller one means the two only touch (depth 0).
Penetration epa_cell_penetration(const Vec3 &cell_center, const Vec3 &cell_half, const Convex &core,
                                 const Simplex &start);

// The same for two convex pieces a and b from gjk_pair_distance's simplex:
// on_shape is a's deepest point in b, on_cell where it leaves b; moving a
// by -depth * normal separates them.  `scale` as in GjkPairQuery.
Penetration epa_pair_penetration(const Convex &a, const Convex &b, double scale, const Simplex &start);

}  // namespace octoprox
