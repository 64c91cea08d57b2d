// Octree cubes as the query engines walk them: the node (nullptr for
// unknown space), its key, and its exact box.  Every face of a box is an
// integer key times the resolution, rounded once, so a child's box taken
// from its parent's mid-planes equals the box computed from its key.
#pragma once

#include "geometry/aabb.hpp"
#include "octree/octree_view.hpp"

namespace octoprox {

struct OctreeCell {
    OctreeView::NodeRef node = nullptr;
    CellKey key;
    Aabb box;
};

// Each face an integer times the resolution, rounded once: the same
// doubles as the parents' mid-planes (key.center of a cell two or more
// cells wide is an integer times the resolution), so cell_box(key) equals
// the box the engines cut from the root with child_cell, bit for bit.
inline Aabb cell_box(const CellKey &key, double resolution) {
    Aabb box;
    const int32_t width = key.width_in_cells();
    for (int axis = 0; axis < 3; ++axis) {
        const int32_t lo = static_cast<int32_t>(key.key[axis]) - kKeyCenter;
        box.lo[axis] = static_cast<double>(lo) * resolution;
        box.hi[axis] = static_cast<double>(lo + width) * resolution;
    }
    return box;
}

inline OctreeCell root_cell(const OctreeView &view) {
    return OctreeCell{view.root(), CellKey{}, cell_box(CellKey{}, view.resolution())};
}

inline Vec3 mid_planes(const OctreeCell &cell, double resolution) {
    return Vec3(cell.key.center(0, resolution), cell.key.center(1, resolution), cell.key.center(2, resolution));
}

// The box of child i (x = bit 0, y = bit 1, z = bit 2) of a cube, cut at
// its mid-planes.
inline Aabb child_box(const Aabb &cube, int i, const Vec3 &mid) {
    Aabb box = cube;
    for (int axis = 0; axis < 3; ++axis) {
        if ((i >> axis) & 1) box.lo[axis] = mid[axis];
        else box.hi[axis] = mid[axis];
    }
    return box;
}

// Child i of a cell, with its key and box.
inline OctreeCell child_cell(const OctreeCell &cell, OctreeView::NodeRef child, int i, const Vec3 &mid) {
    return OctreeCell{child, cell.key.child(i), child_box(cell.box, i, mid)};
}

// The part of an inner cell's cube holding its obstacle leaves, from the
// view's packed slots (bounded_tree.hpp), padded outwards by `pad` (see
// obstacle_box_pad) so it always contains every obstacle leaf's exact box.
// The traversals decode a box per child they bound: a table of slot
// numbers and constant shifts instead of a loop of int-to-double
// conversions save 4% of a whole scene F distance query (callgrind).
inline Aabb obstacle_box(const Aabb &cube, uint32_t packed, double pad) {
    static constexpr double kSlot[33] = {0,  1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 12, 13, 14, 15, 16,
                                         17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32};
    const double slot = (cube.hi.x() - cube.lo.x()) * (1.0 / 32);
    return Aabb{Vec3(cube.lo.x() + slot * kSlot[packed & 31] - pad, cube.lo.y() + slot * kSlot[(packed >> 5) & 31] - pad,
                     cube.lo.z() + slot * kSlot[(packed >> 10) & 31] - pad),
                Vec3(cube.lo.x() + slot * kSlot[((packed >> 15) & 31) + 1] + pad,
                     cube.lo.y() + slot * kSlot[((packed >> 20) & 31) + 1] + pad,
                     cube.lo.z() + slot * kSlot[((packed >> 25) & 31) + 1] + pad)};
}

inline Aabb obstacle_box(const OctreeCell &cell, uint32_t packed, double pad) { return obstacle_box(cell.box, packed, pad); }

// Whether the finest cells holding a cube's obstacle leaves, from its
// packed slots, meet the cells [lo, hi] (per axis): integers only, exact
// (a slot is a whole number of cells or a whole fraction of one).  The
// cube's minimum key is cube_lo and it is 2^width_bits cells wide.
inline bool obstacle_cells_meet(uint32_t packed, const int32_t cube_lo[3], int width_bits, const int32_t lo[3],
                                const int32_t hi[3]) {
    for (int axis = 0; axis < 3; ++axis) {
        const int32_t first_slot = (packed >> (5 * axis)) & 31, last_slot = (packed >> (15 + 5 * axis)) & 31;
        const int32_t first = cube_lo[axis] + ((first_slot << width_bits) >> 5);
        const int32_t last = cube_lo[axis] + ((((last_slot + 1) << width_bits) - 1) >> 5);
        if (last < lo[axis] || first > hi[axis]) return false;
    }
    return true;
}

// Thousands of times the rounding error of any coordinate in the map cube
// (|x| <= kKeyCenter * resolution), and still far below a micrometre.
inline double obstacle_box_pad(double resolution) { return 1e-12 * kKeyCenter * resolution; }

// What a query takes as the obstacles of the map's cells.
struct ObstacleModel {
    // The map's inner obstacle boxes hold: the query's obstacles are the
    // leaves at or above a threshold >= the view's bounds_threshold.
    bool inner_boxes = false;
    // An obstacle leaf is the box of its sensed points when it keeps one
    // (OPX_OBSTACLE_POINT_EXTENTS), else its cube.
    bool point_extents = false;
    float threshold = 0.0f;  // leaves at or above it are obstacles
    double pad = 0.0;        // obstacle_box_pad of the map
};

// What the obstacles of a cell's subtree can lie in.  An inner node: the
// box of its obstacle leaves when the model's inner_boxes and the node
// keeps one, else its cube.  A leaf (or unknown space, node nullptr): its
// point extent when the model asks for extents, the leaf is an obstacle
// and keeps one, else its cube; so a leaf's bounds are exactly the box
// its obstacle test uses.  `inner`: the cell's node has children (a caller
// that knows it already saves OctoMap's scan of the child pointers).
inline Aabb obstacle_bounds(const OctreeView &view, OctreeView::NodeRef node, const Aabb &cube,
                            const ObstacleModel &model, bool inner) {
    if (inner) {
        if (!model.inner_boxes) return cube;
        const uint32_t packed = view.packed_obstacle_bounds(node);
        return packed != 0 ? obstacle_box(cube, packed, model.pad) : cube;
    }
    if (model.point_extents && node != nullptr && view.log_odds(node) >= model.threshold) {
        const uint32_t packed = view.point_extent(node);
        if (packed != 0) return obstacle_box(cube, packed, model.pad);
    }
    return cube;
}

inline Aabb obstacle_bounds(const OctreeView &view, const OctreeCell &cell, const ObstacleModel &model,
                            bool inner) {
    return obstacle_bounds(view, cell.node, cell.box, model, inner);
}

inline bool is_inner(const OctreeView &view, const OctreeCell &cell) {
    return cell.node != nullptr && view.has_children(cell.node);
}

inline Aabb obstacle_bounds(const OctreeView &view, const OctreeCell &cell, const ObstacleModel &model) {
    return obstacle_bounds(view, cell, model, is_inner(view, cell));
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
