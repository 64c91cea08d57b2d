// The engines' read-only view of an occupancy octree.
//
// Query engines see the map only through this class: nodes as opaque
// references, children by index, log-odds per node (an inner node holds the
// maximum of its children, which makes pruning by threshold safe), and cell
// geometry from integer keys, and for inner nodes the part of their cube
// that holds their obstacle leaves.  The storage behind it is OctoMap's
// occupancy octree (bounded_tree.hpp); replacing it means rewriting
// octree_view_octomap.inl only.
#pragma once

#include <cstdint>

namespace octoprox {

// Depth of the finest cells; the root cube is 2^kTreeDepth cells wide.
constexpr int kTreeDepth = 16;
constexpr int32_t kKeyCenter = 1 << (kTreeDepth - 1);

// A cube of the tree: the integer key of its minimum corner at the finest
// depth, and its depth (0 = root).  Geometry follows exactly OctoMap's
// keyToCoord, so centers match OctoMap's bit for bit.
struct CellKey {
    uint16_t key[3] = {0, 0, 0};
    int depth = 0;

    int32_t width_in_cells() const { return 1 << (kTreeDepth - depth); }
    // Child i: x = bit 0, y = bit 1, z = bit 2 (OctoMap's order).
    CellKey child(int i) const {
        CellKey c;
        const int32_t half = width_in_cells() / 2;
        for (int axis = 0; axis < 3; ++axis)
            c.key[axis] = static_cast<uint16_t>(key[axis] + (((i >> axis) & 1) ? half : 0));
        c.depth = depth + 1;
        return c;
    }
    double center(int axis, double resolution) const {
        return (key[axis] - kKeyCenter + 0.5 * width_in_cells()) * resolution;
    }
    double size(double resolution) const { return width_in_cells() * resolution; }
};

class OctreeView {
public:
    using NodeRef = const void *;

    // bounds_threshold: the log-odds the map's obstacle boxes are kept for.
    OctreeView(const void *bounded_tree, float bounds_threshold);

    double resolution() const { return resolution_; }
    NodeRef root() const;                       // nullptr when the map is empty
    bool has_children(NodeRef node) const;
    NodeRef child(NodeRef node, int index) const;  // nullptr: unknown space
    // For a node with children: the child, or for unknown space a leaf with
    // log-odds -infinity, without reading the child pointer.  For searches
    // to which unknown space is no obstacle, as cells below any threshold.
    NodeRef child_or_absent(NodeRef node, int index) const;
    float log_odds(NodeRef node) const;
    // For a node with children: its obstacle box packed as in
    // bounded_tree.hpp (0 when not known).  Valid for a query whose
    // obstacles are leaves at or above a threshold >= bounds_threshold().
    uint32_t packed_obstacle_bounds(NodeRef node) const;
    float bounds_threshold() const { return bounds_threshold_; }
    // For a leaf: the box of the sensed points in it, packed as in
    // point_extent.hpp (0 when it has none: the whole cube).
    uint32_t point_extent(NodeRef node) const;
    // Asks the CPU to fetch the children in `mask` (bit i: child i) ahead,
    // so that a traversal reading them does not wait for each in turn.
    void prefetch_children(NodeRef node, unsigned mask) const;

private:
    const void *tree_;
    double resolution_;
    float bounds_threshold_;
};

}  // namespace octoprox

#include "octree/octree_view_octomap.inl"
