// Exact distance between one placed shape (padding included) and one cell.
#pragma once

#include "robot/shape.hpp"

namespace octoprox {

struct ShapeCellDistance {
    double distance = 0.0;  // >= 0; 0 when they touch or overlap
    Vec3 on_shape = Vec3::Zero();  // on the padded shape's surface
    Vec3 on_cell = Vec3::Zero();
};

// Distance of the padded shape to the cell box; gives up early (returns
// false) when it is proven to be at least `bound`.
bool shape_cell_distance(const PlacedShape &shape, const Vec3 &cell_center, const Vec3 &cell_half,
                         double bound, ShapeCellDistance &out, uint64_t &narrow_tests);

}  // namespace octoprox
