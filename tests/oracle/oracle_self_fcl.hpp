// A cylinder against another convex piece, measured by FCL with both of its
// GJK solvers (GST_INDEP and GST_LIBCCD, tolerance 1e-12): two independent
// implementations that agree to 1e-7 m are trusted (as oracle_fcl does for
// cylinders against cells); the caller brackets the pair with prisms when
// they do not.
#pragma once

#include "oracle_pieces.hpp"

namespace oracle {

// `cylinder` is a Piece::kCylinder; `other` any piece.  The distance (0
// when they intersect) in `out`, or false when the solvers disagree.
bool fcl_cylinder_distance(const Piece &cylinder, const Piece &other, double &out);

}  // namespace oracle
