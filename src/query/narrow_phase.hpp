// Exact tests between one placed shape (padding included) and one cell.
#pragma once

#include "robot/shape.hpp"

namespace octoprox {

// Shapes within this distance of a cell (after padding) touch it: touching
// counts as collision (closed sets), and this absorbs the rounding of
// coordinates so that flush faces and tangent spheres are decided the same
// way every time.  See docs/geometry.md.
constexpr double kTouchTolerance = 1e-9;

// Is the (inflated) shape within kTouchTolerance of the cell box?
// narrow_tests counts the exact convex-vs-cell tests it ran.
bool shape_touches_cell(const PlacedShape &shape, const Vec3 &cell_center, const Vec3 &cell_half,
                        uint64_t &narrow_tests);

}  // namespace octoprox
