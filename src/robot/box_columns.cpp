#include "robot/box_columns.hpp"

#include "base/avx2.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {
namespace {

void pad_to_lanes(BoxColumns &columns) {
    const size_t padded = (columns.count + 3) / 4 * 4;
    for (int axis = 0; axis < 3; ++axis) {
        columns.center[axis].resize(padded, columns.center[axis][0]);
        columns.half[axis].resize(padded, columns.half[axis][0]);
    }
}

}  // namespace

BoxColumns box_columns(const std::vector<Aabb> &boxes) {
    BoxColumns columns;
    columns.count = boxes.size();
    if (boxes.empty()) return columns;
    for (const Aabb &box : boxes) {
        for (int axis = 0; axis < 3; ++axis) {
            columns.center[axis].push_back(0.5 * (box.lo[axis] + box.hi[axis]));
            columns.half[axis].push_back(0.5 * (box.hi[axis] - box.lo[axis]));
        }
    }
    pad_to_lanes(columns);
    return columns;
}

BoxColumns point_columns(const std::vector<Vec3> &points) {
    BoxColumns columns;
    columns.count = points.size();
    if (points.empty()) return columns;
    for (const Vec3 &p : points) {
        for (int axis = 0; axis < 3; ++axis) {
            columns.center[axis].push_back(p[axis]);
            columns.half[axis].push_back(0.0);
        }
    }
    pad_to_lanes(columns);
    return columns;
}

void placed_union_portable(const BoxColumns &boxes, const double r[3][3], const double s[3][3], const double t[3],
                           double lo[3], double hi[3]) {
    for (size_t b = 0; b < boxes.count; ++b) {
        const double c[3] = {boxes.center[0][b], boxes.center[1][b], boxes.center[2][b]};
        const double h[3] = {boxes.half[0][b], boxes.half[1][b], boxes.half[2][b]};
        for (int i = 0; i < 3; ++i) {
            const double middle = r[i][0] * c[0] + r[i][1] * c[1] + r[i][2] * c[2] + t[i];
            const double half = s[i][0] * h[0] + s[i][1] * h[1] + s[i][2] * h[2];
            lo[i] = std::min(lo[i], middle - half);
            hi[i] = std::max(hi[i], middle + half);
        }
    }
}

Aabb placed_union(const BoxColumns &boxes, const Eigen::Matrix3d &rotation, const Vec3 &center) {
    if (boxes.count == 0) return Aabb();
    double r[3][3], s[3][3], t[3], lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) r[i][j] = rotation(i, j), s[i][j] = std::fabs(rotation(i, j));
        t[i] = center[i];
        lo[i] = std::numeric_limits<double>::infinity(), hi[i] = -lo[i];
    }
    if (cpu_has_avx2()) placed_union_avx2(boxes, r, s, t, lo, hi);
    else placed_union_portable(boxes, r, s, t, lo, hi);
    Aabb placed{Vec3(lo[0], lo[1], lo[2]), Vec3(hi[0], hi[1], hi[2])};
    pad_placed_box(placed, center);
    return placed;
}

void pad_placed_box(Aabb &placed, const Vec3 &center) {
    placed.inflate(1e-12 * (1.0 + center.cwiseAbs().maxCoeff() + (placed.hi - placed.lo).maxCoeff()));
}

}  // namespace octoprox
