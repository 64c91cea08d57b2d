// Exact tests between two placed shapes, both padded: the narrow phase of
// self-collision.  Touching counts (closed sets, within kTouchTolerance);
// a mesh is a surface, as against cells: a shape wholly inside a closed
// mesh touches none of its triangles.
#pragma once

#include "robot/shape.hpp"

#include <cstdint>

namespace octoprox {

// Do the padded shapes touch?  narrow_tests counts the exact piece tests.
bool shapes_touch(const PlacedShape &a, const PlacedShape &b, uint64_t &narrow_tests);

struct ShapePairDistance {
    double distance = 0.0;     // >= 0; 0 when they touch or overlap
    Vec3 on_a = Vec3::Zero();  // on a's padded surface, map frame
    Vec3 on_b = Vec3::Zero();  // on b's; `distance` apart (one common point at 0)
};

// The padded shapes' distance when below `bound` (false: proven at least
// `bound`, `out` untouched).  Meshes are placed for it (PlacedShape::place_mesh).
bool shape_pair_distance(const PlacedShape &a, const PlacedShape &b, double bound, ShapePairDistance &out,
                         uint64_t &narrow_tests);

struct ShapePairPenetration {
    double depth = 0.0;           // >= 0, paddings included
    Vec3 normal = Vec3::UnitX();  // moving a by -depth * normal separates the pair
    Vec3 on_a = Vec3::Zero();     // a's padded point deepest in b, map frame
    Vec3 on_b = Vec3::Zero();     // b's padded point deepest in a: on_a - depth * normal
};

// For shapes that touch: their deepest pair of pieces (for a mesh, its
// deepest triangle).
ShapePairPenetration shape_pair_penetration(const PlacedShape &a, const PlacedShape &b, uint64_t &narrow_tests);

}  // namespace octoprox
