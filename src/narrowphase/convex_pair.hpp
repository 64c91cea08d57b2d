// Exact tests between two convex pieces, each with the ball of its shape's
// padding (its inflation): the building block of the shape-pair tests
// (shape_pair.hpp).  A piece is a shape's core, or one triangle of a mesh.
#pragma once

#include "geometry/convex.hpp"

#include <cstdint>

namespace octoprox {

// One side of a pair: a convex piece and the radius of the ball around it.
struct InflatedPiece {
    const Convex *core = nullptr;
    double inflation = 0.0;
};

struct PiecePairDistance {
    double distance = 0.0;       // >= 0; 0 when the padded pieces touch or overlap
    Vec3 on_a = Vec3::Zero();    // on a's padded surface (one common point at 0)
    Vec3 on_b = Vec3::Zero();
};

// Is the padded pair within `limit` of touching (distance <= limit)?
// `scale`: about the pieces' size, for GJK's rounding floor.
bool pieces_within(const InflatedPiece &a, const InflatedPiece &b, double limit, double scale);

// The padded pieces' distance with witnesses, when below `bound` (false:
// proven at least `bound`, `out` untouched).
bool piece_pair_distance(const InflatedPiece &a, const InflatedPiece &b, double scale, double bound,
                         PiecePairDistance &out);

struct PiecePairPenetration {
    double depth = 0.0;           // of the padded pieces, >= 0 when they touch
    Vec3 normal = Vec3::UnitX();  // moving a by -depth * normal separates the pair
    Vec3 on_a = Vec3::Zero();     // a's padded point deepest in b
    Vec3 on_b = Vec3::Zero();     // b's padded point deepest in a (on_a - depth * normal)
};

// How deep the padded pieces overlap (negative: their gap).
PiecePairPenetration piece_pair_penetration(const InflatedPiece &a, const InflatedPiece &b, double scale);

}  // namespace octoprox
