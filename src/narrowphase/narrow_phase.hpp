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

// A cheap conservative test for octree descent: false only when the shape
// surely does not touch the box.  Tighter than the shape's bounding box
// for spheres (true distance) and for rotated boxes, cylinders, capsules
// and meshes (their oriented box, by the 6 face axes; a mesh's is its
// triangle tree's box in its own frame).
bool shape_may_touch(const PlacedShape &shape, const Aabb &box);

// A lower bound of the padded shape's distance to the box (may be
// negative): the true distance for spheres; for boxes the gap along the 3
// face axes of the box, and for meshes along those of the oriented root
// box of its tree; for cylinders and capsules the box's gaps across and
// along their axis, combined in quadrature; the box distance otherwise.
// Callers take the maximum with the distance of the shape's axis-aligned
// box, which covers the map's own axes.
double shape_lower_bound(const PlacedShape &shape, const Aabb &box);

}  // namespace octoprox
