#include "edt_reference.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace spheres_bench {
namespace {

constexpr double kFar = 1e20;

// The lower envelope of the parabolas (q - i)^2 + f[i] over one line.
void envelope(const double *f, size_t n, double *out, std::vector<size_t> &v, std::vector<double> &z) {
    v.assign(n, 0);
    z.assign(n + 1, 0.0);
    size_t k = 0;
    z[0] = -std::numeric_limits<double>::infinity();
    z[1] = std::numeric_limits<double>::infinity();
    for (size_t q = 1; q < n; ++q) {
        double s;
        for (;;) {
            const size_t p = v[k];
            s = ((f[q] + double(q) * double(q)) - (f[p] + double(p) * double(p))) / (2.0 * double(q) - 2.0 * double(p));
            if (s > z[k] || k == 0) break;
            --k;
        }
        if (s <= z[k]) {  // k == 0 and the new parabola is lower everywhere
            v[0] = q;
            z[1] = std::numeric_limits<double>::infinity();
            continue;
        }
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = std::numeric_limits<double>::infinity();
    }
    k = 0;
    for (size_t q = 0; q < n; ++q) {
        while (z[k + 1] < double(q)) ++k;
        const double d = double(q) - double(v[k]);
        out[q] = d * d + f[v[k]];
    }
}

}  // namespace

DistanceGrid::DistanceGrid(const double lo[3], const size_t size[3], double voxel, const std::vector<double> &occupied)
    : voxel_(voxel) {
    for (int a = 0; a < 3; ++a) lo_[a] = lo[a], size_[a] = size[a];
    field_.assign(size_[0] * size_[1] * size_[2], kFar);
    for (size_t i = 0; i + 2 < occupied.size(); i += 3) {
        size_t at[3];
        bool inside = true;
        for (int a = 0; a < 3; ++a) {
            const double v = std::floor((occupied[i + a] - lo_[a]) / voxel_);
            inside = inside && v >= 0.0 && v < double(size_[a]);
            at[a] = inside ? size_t(v) : 0;
        }
        if (inside) field_[index(at[0], at[1], at[2])] = 0.0;
    }
    for (int axis = 0; axis < 3; ++axis) transform_axis(axis);
    for (double &d : field_) d = std::sqrt(d) * voxel_;
}

void DistanceGrid::transform_axis(int axis) {
    const size_t n = size_[axis];
    const size_t stride = axis == 0 ? 1 : axis == 1 ? size_[0] : size_[0] * size_[1];
    std::vector<double> line(n), out(n), z;
    std::vector<size_t> v;
    const size_t lines = field_.size() / n;
    for (size_t l = 0; l < lines; ++l) {
        // The first element of line l: the other two axes' coordinates.
        size_t start;
        if (axis == 0) start = l * n;
        else if (axis == 1) start = (l / size_[0]) * size_[0] * size_[1] + l % size_[0];
        else start = l;
        for (size_t q = 0; q < n; ++q) line[q] = field_[start + q * stride];
        envelope(line.data(), n, out.data(), v, z);
        for (size_t q = 0; q < n; ++q) field_[start + q * stride] = out[q];
    }
}

double DistanceGrid::lookup(const double p[3], double gradient[3]) const {
    size_t i0[3];
    double t[3];
    for (int a = 0; a < 3; ++a) {
        const double u = std::clamp((p[a] - lo_[a]) / voxel_ - 0.5, 0.0, double(size_[a]) - 1.000001);
        i0[a] = size_t(u);
        t[a] = u - double(i0[a]);
    }
    double c[8];
    for (int k = 0; k < 8; ++k) c[k] = field_[index(i0[0] + (k & 1), i0[1] + ((k >> 1) & 1), i0[2] + (k >> 2))];
    const double x00 = c[0] + t[0] * (c[1] - c[0]), x10 = c[2] + t[0] * (c[3] - c[2]);
    const double x01 = c[4] + t[0] * (c[5] - c[4]), x11 = c[6] + t[0] * (c[7] - c[6]);
    const double y0 = x00 + t[1] * (x10 - x00), y1 = x01 + t[1] * (x11 - x01);
    const double dx0 = (c[1] - c[0]) + t[1] * ((c[3] - c[2]) - (c[1] - c[0]));
    const double dx1 = (c[5] - c[4]) + t[1] * ((c[7] - c[6]) - (c[5] - c[4]));
    gradient[0] = (dx0 + t[2] * (dx1 - dx0)) / voxel_;
    gradient[1] = ((x10 - x00) + t[2] * ((x11 - x01) - (x10 - x00))) / voxel_;
    gradient[2] = (y1 - y0) / voxel_;
    return y0 + t[2] * (y1 - y0);
}

}  // namespace spheres_bench
