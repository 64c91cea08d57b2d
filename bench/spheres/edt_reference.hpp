// The pipeline a grid-based optimizer runs per frame, as a reference for
// opx-bench-spheres: an exact Euclidean distance transform of the map's
// occupied cells over a box (Felzenszwalb and Huttenlocher's separable
// lower envelopes, one pass per axis), then per sphere a trilinear lookup
// of the distance and its gradient.  Distances run between voxel centres
// (an occupied voxel is 0), as in voxel distance fields.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace spheres_bench {

class DistanceGrid {
public:
    // Voxels of `voxel` metres over [lo, lo + voxel * size); `occupied`
    // holds the centres of the occupied cells (x y z packed).
    DistanceGrid(const double lo[3], const size_t size[3], double voxel, const std::vector<double> &occupied);

    // Distance (metres, unsigned) at a point and its gradient, trilinear.
    double lookup(const double p[3], double gradient[3]) const;

private:
    void transform_axis(int axis);
    size_t index(size_t x, size_t y, size_t z) const { return (z * size_[1] + y) * size_[0] + x; }

    double lo_[3], voxel_;
    size_t size_[3];
    std::vector<double> field_;  // squared distances in voxels, then metres
};

}  // namespace spheres_bench
