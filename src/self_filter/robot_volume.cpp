#include "self_filter/robot_volume.hpp"

#include "base/error.hpp"
#include "broadphase/morton.hpp"
#include "octree/octree_cell.hpp"
#include "self_filter/mesh_solid.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

constexpr int64_t kKeyCount = int64_t{2} * kKeyCenter;  // keys per axis

// The key range [lo, hi] of the cells meeting [a, b] along one axis, cut
// to the map; false when empty.
bool key_range(double a, double b, double resolution, int64_t &lo, int64_t &hi) {
    const double first = std::floor(a / resolution) + kKeyCenter, last = std::floor(b / resolution) + kKeyCenter;
    if (!(first <= last) || last < 0.0 || first >= static_cast<double>(kKeyCount)) return false;
    lo = static_cast<int64_t>(std::max(first, 0.0));
    hi = static_cast<int64_t>(std::min(last, static_cast<double>(kKeyCount - 1)));
    return true;
}

// A finest cell's lowest coordinate along an axis, as cell_box gives it.
double corner(int64_t key, double resolution) { return static_cast<double>(key - kKeyCenter) * resolution; }

// The keys of the cells meeting the unpadded solid's box; false when none.
bool solid_keys(const FilterSolid &solid, double resolution, int64_t lo[3], int64_t hi[3]) {
    Aabb box = solid.shape->box;
    box.inflate(solid.solid_radius - solid.shape->inflation);
    for (int axis = 0; axis < 3; ++axis)
        if (!key_range(box.lo[axis], box.hi[axis], resolution, lo[axis], hi[axis])) return false;
    return true;
}

void require_bounded_volume(const PaddedRobot &robot, double resolution) {
    double corners = 0.0;
    for (const FilterSolid &solid : robot.solids()) {
        int64_t lo[3], hi[3];
        if (!solid_keys(solid, resolution, lo, hi)) continue;
        corners += double(hi[0] - lo[0] + 2) * double(hi[1] - lo[1] + 2) * double(hi[2] - lo[2] + 2);
    }
    if (corners > kMaxVolumeCorners)
        throw_invalid(format("options.clear_robot_volume: the robot's solids span %.3g cell corners at a "
                             "resolution of %g m, more than the %.3g the clearing tests",
                             corners, resolution, kMaxVolumeCorners));
}

void add_solid_cells(const FilterSolid &solid, double resolution, std::vector<uint64_t> &out) {
    int64_t lo[3], hi[3];
    if (!solid_keys(solid, resolution, lo, hi)) return;
    // The corners' grid, each corner tested once for the cells around it.
    const int64_t n[3] = {hi[0] - lo[0] + 2, hi[1] - lo[1] + 2, hi[2] - lo[2] + 2};
    std::vector<char> inside(static_cast<size_t>(n[0] * n[1] * n[2]));
    const auto at = [&](int64_t x, int64_t y, int64_t z) { return static_cast<size_t>((z * n[1] + y) * n[0] + x); };
    for (int64_t z = 0; z < n[2]; ++z)
        for (int64_t y = 0; y < n[1]; ++y)
            for (int64_t x = 0; x < n[0]; ++x) {
                const Vec3 p(corner(lo[0] + x, resolution), corner(lo[1] + y, resolution), corner(lo[2] + z, resolution));
                inside[at(x, y, z)] = solid.holds(p, solid.solid_radius) ? 1 : 0;
            }
    for (int64_t z = 0; z + 1 < n[2]; ++z)
        for (int64_t y = 0; y + 1 < n[1]; ++y)
            for (int64_t x = 0; x + 1 < n[0]; ++x) {
                bool all = true;
                for (int c = 0; c < 8 && all; ++c) all = inside[at(x + (c & 1), y + ((c >> 1) & 1), z + (c >> 2))] != 0;
                if (!all) continue;
                const int64_t key[3] = {lo[0] + x, lo[1] + y, lo[2] + z};
                if (solid.closed_mesh) {
                    CellKey cell;
                    cell.depth = kTreeDepth;
                    for (int axis = 0; axis < 3; ++axis) cell.key[axis] = static_cast<uint16_t>(key[axis]);
                    if (MeshSolid(*solid.shape, solid.solid_radius).touches_box(cell_box(cell, resolution))) continue;
                }
                out.push_back(morton_encode(static_cast<uint32_t>(key[0]), static_cast<uint32_t>(key[1]),
                                            static_cast<uint32_t>(key[2])));
            }
}

}  // namespace

std::vector<uint64_t> robot_volume_cells(const PaddedRobot &robot, double resolution) {
    require_bounded_volume(robot, resolution);
    std::vector<uint64_t> cells;
    for (const FilterSolid &solid : robot.solids()) add_solid_cells(solid, resolution, cells);
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
    return cells;
}

}  // namespace octoprox
