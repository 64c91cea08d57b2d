// Octree cubes as the query engines walk them: the node (nullptr for
// unknown space), its key, and its exact box.  Every face of a box is an
// integer key times the resolution, rounded once, so a child's box taken
// from its parent's mid-planes equals the box computed from its key.
#pragma once

#include "geometry/aabb.hpp"
#include "octree/octree_view.hpp"

#include <cmath>

namespace octoprox {

struct OctreeCell {
    OctreeView::NodeRef node = nullptr;
    CellKey key;
    Aabb box;
};

inline Aabb cell_box(const CellKey &key, double resolution) {
    const double half = 0.5 * key.size(resolution);
    const Vec3 center(key.center(0, resolution), key.center(1, resolution), key.center(2, resolution));
    return Aabb::from_center(center, Vec3::Constant(half));
}

inline OctreeCell root_cell(const OctreeView &view) {
    return OctreeCell{view.root(), CellKey{}, cell_box(CellKey{}, view.resolution())};
}

inline Vec3 mid_planes(const OctreeCell &cell, double resolution) {
    return Vec3(cell.key.center(0, resolution), cell.key.center(1, resolution), cell.key.center(2, resolution));
}

// Child i of a cell (x = bit 0, y = bit 1, z = bit 2), its box cut at the mid-planes.
inline OctreeCell child_cell(const OctreeCell &cell, OctreeView::NodeRef child, int i, const Vec3 &mid) {
    OctreeCell c{child, cell.key.child(i), cell.box};
    for (int axis = 0; axis < 3; ++axis) {
        if ((i >> axis) & 1) c.box.lo[axis] = mid[axis];
        else c.box.hi[axis] = mid[axis];
    }
    return c;
}

// The part of an inner cell's cube holding its obstacle leaves, from the
// view's packed slots (bounded_tree.hpp), padded outwards by far more than
// rounding so it always contains every obstacle leaf's exact box.
inline Aabb obstacle_box(const OctreeCell &cell, uint32_t packed) {
    constexpr double kSlot = 1.0 / 32;
    const Vec3 width = cell.box.hi - cell.box.lo;
    Aabb box;
    for (int axis = 0; axis < 3; ++axis) {
        const double pad = 1e-12 * (std::abs(cell.box.lo[axis]) + width[axis]);
        box.lo[axis] = cell.box.lo[axis] + width[axis] * (kSlot * ((packed >> (5 * axis)) & 31)) - pad;
        box.hi[axis] = cell.box.lo[axis] + width[axis] * (kSlot * (((packed >> (15 + 5 * axis)) & 31) + 1)) + pad;
    }
    return box;
}

// The children (bit i for child i) that a box overlapping the parent can
// overlap, from the sides of the mid-planes it reaches (closed boxes).
inline unsigned children_overlapping(const Aabb &box, const Vec3 &mid) {
    static const unsigned kLowSide[3] = {0x55, 0x33, 0x0F};  // children with bit `axis` clear
    unsigned mask = 0xFF;
    for (int axis = 0; axis < 3; ++axis) {
        if (box.lo[axis] > mid[axis]) mask &= ~kLowSide[axis];
        if (box.hi[axis] < mid[axis]) mask &= kLowSide[axis];
    }
    return mask;
}

}  // namespace octoprox
