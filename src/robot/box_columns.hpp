// Many boxes placed at once (a mesh's bounds after each pose update): the
// boxes stored by coordinate, so that four are placed per step with AVX2
// where the processor has it (chosen at run time), one by one elsewhere.
#pragma once

#include "geometry/aabb.hpp"

#include <vector>

namespace octoprox {

// Centres and half extents by axis, each array padded to a multiple of 4
// with copies of box 0 (which change no union).
struct BoxColumns {
    std::vector<double> center[3], half[3];
    size_t count = 0;  // boxes before padding
};

BoxColumns box_columns(const std::vector<Aabb> &boxes);
// Points as boxes without extent.
BoxColumns point_columns(const std::vector<Vec3> &points);

// The union of the boxes after p -> rotation * p + center, each placed as
// the axis-aligned box of the rotated box, padded (pad_placed_box).  An
// empty box for no boxes.
Aabb placed_union(const BoxColumns &boxes, const Eigen::Matrix3d &rotation, const Vec3 &center);

// Grows a box placed by p -> rotation * p + center by 1e-12 relative, for
// the rounding of placing it and of placing the vertices it bounds
// (place_mesh): the box still holds every placed vertex.
void pad_placed_box(Aabb &placed, const Vec3 &center);

// The AVX2 (where cpu_has_avx2(), base/avx2.hpp) and the portable loops
// behind placed_union (box_columns_avx2.cpp, box_columns.cpp): lo and hi of
// the union before padding, grown from their values on entry; both round
// alike (no fused multiply-add).
void placed_union_portable(const BoxColumns &boxes, const double r[3][3], const double s[3][3], const double t[3],
                           double lo[3], double hi[3]);
void placed_union_avx2(const BoxColumns &boxes, const double r[3][3], const double s[3][3], const double t[3],
                       double lo[3], double hi[3]);

}  // namespace octoprox
