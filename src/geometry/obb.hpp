// Oriented boxes in the map frame and a conservative overlap test between
// two of them, for culling pairs of shapes (and of mesh tree nodes) before
// their exact test.
#pragma once

#include "geometry/pose.hpp"

#include <cmath>

namespace octoprox {

struct Obb {
    Vec3 center = Vec3::Zero();
    Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();  // columns: the box's x, y, z
    Vec3 half = Vec3::Zero();                            // half edges, >= 0
};

// False only when the boxes are more than `margin` apart along one of the
// 15 separating axes (the 3 + 3 face normals and the 9 edge cross
// products): then every pair of points, one in each box, is more than
// `margin` apart.  Near-parallel edges make a cross product tiny; the
// small term added to the absolute rotation keeps those axes from
// separating boxes by rounding.
inline bool obbs_within(const Obb &a, const Obb &b, double margin) {
    const Eigen::Matrix3d r = a.axes.transpose() * b.axes;  // b's axes in a's frame
    const Eigen::Matrix3d abs_r = r.cwiseAbs().array() + 1e-12;
    const Vec3 t = a.axes.transpose() * (b.center - a.center);
    for (int i = 0; i < 3; ++i)
        if (std::fabs(t[i]) > a.half[i] + abs_r.row(i).dot(b.half) + margin) return false;
    for (int j = 0; j < 3; ++j)
        if (std::fabs(t.dot(r.col(j))) > abs_r.col(j).dot(a.half) + b.half[j] + margin) return false;
    // Axis a_i x b_j: its length is at most 1, so `margin` bounds the gap
    // along the unit axis from above as well.
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const double ra = a.half[i1] * abs_r(i2, j) + a.half[i2] * abs_r(i1, j);
            const double rb = b.half[j1] * abs_r(i, j2) + b.half[j2] * abs_r(i, j1);
            if (std::fabs(t[i2] * r(i1, j) - t[i1] * r(i2, j)) > ra + rb + margin) return false;
        }
    }
    return true;
}

}  // namespace octoprox
