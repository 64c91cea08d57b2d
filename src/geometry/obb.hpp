// Overlap tests between boxes in two frames, for culling pairs of shapes
// (and of mesh tree nodes) before their exact test.  Each box is
// axis-aligned in its own frame (a mesh's tree nodes in the mesh frame, a
// box shape in its shape frame); the frame of B seen from A's is computed
// once per pair of shapes, so a test costs the 15 separating axes alone.
#pragma once

#include "geometry/pose.hpp"

#include <cmath>

namespace octoprox {

// B's frame in A's: p_a = rotation * p_b + translation, from both frames'
// poses in the map (p_map = r * p + o).
struct RelativeFrame {
    Eigen::Matrix3d rotation;
    // |rotation| plus a small term: near-parallel edges make a cross
    // product axis tiny, and the term keeps it from separating boxes by
    // rounding.
    Eigen::Matrix3d abs_rotation;
    Vec3 translation;

    RelativeFrame(const Eigen::Matrix3d &ra, const Vec3 &oa, const Eigen::Matrix3d &rb, const Vec3 &ob)
        : rotation(ra.transpose() * rb), translation(ra.transpose() * (ob - oa)) {
        abs_rotation = rotation.cwiseAbs().array() + 1e-12;
    }
};

// False only when box A (centre ca, half edges ha, in A's frame) and box B
// (cb, hb, in B's frame) are more than `margin` apart along one of the 15
// separating axes (3 + 3 face normals, 9 edge cross products): then every
// pair of points, one in each box, is more than `margin` apart.
inline bool boxes_within(const Vec3 &ca, const Vec3 &ha, const Vec3 &cb, const Vec3 &hb, const RelativeFrame &f,
                         double margin) {
    const Eigen::Matrix3d &r = f.rotation, &abs_r = f.abs_rotation;
    const Vec3 t = r * cb + f.translation - ca;
    for (int i = 0; i < 3; ++i)
        if (std::fabs(t[i]) > ha[i] + abs_r.row(i).dot(hb) + margin) return false;
    for (int j = 0; j < 3; ++j)
        if (std::fabs(t.dot(r.col(j))) > abs_r.col(j).dot(ha) + hb[j] + margin) return false;
    // Axis a_i x b_j is at most 1 long, so `margin` bounds the gap along
    // the unit axis from above as well.
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            const double ra = ha[i1] * abs_r(i2, j) + ha[i2] * abs_r(i1, j);
            const double rb = hb[j1] * abs_r(i, j2) + hb[j2] * abs_r(i, j1);
            if (std::fabs(t[i2] * r(i1, j) - t[i1] * r(i2, j)) > ra + rb + margin) return false;
        }
    }
    return true;
}

}  // namespace octoprox
