// Where a single shape enters the octree: the cubes, at the depth where
// cubes are at least as wide as the shape's reach, that the reach
// overlaps (at most two a side, so at most eight), found from their keys.
// A search that starts there skips the levels above, where a shape's box
// would be bounded against cube after cube only to enter each of them, and
// it needs no robot tree to carry it down.
#pragma once

#include "octree/octree_cell.hpp"

namespace octoprox {

// The finest-cell keys a box covers, per axis [lo, hi], with the cell
// beyond taken too where a face lies within rounding of a cell face.
struct KeyRange {
    int32_t lo[3];
    int32_t hi[3];
};

// At most eight cubes; a leaf above the entry depth stands for the cubes
// it holds, once.
struct CubeEntries {
    OctreeCell cells[8];
    int count = 0;
};

class CubeEntryFinder {
public:
    explicit CubeEntryFinder(const OctreeView &view);

    // The cubes that hold obstacles at or above `threshold` (an inner
    // node's log-odds is its subtree's maximum) and that the finite box
    // `reach` overlaps.  Unknown space is left out: only for queries where
    // unknown is free.  With `use_boxes` (the threshold is at or above the
    // view's bounds_threshold), an inner cube is left out too when the
    // cells of its obstacle box (octree_cell.hpp) are all beyond the reach:
    // an integer test that spares the caller a cube it would prune anyway.
    void find(const Aabb &reach, float threshold, bool use_boxes, CubeEntries &entries);

private:
    // False when the box lies wholly outside the map cube.
    bool key_range_of(const Aabb &box, KeyRange &range) const;
    // The node of the cube at `depth` whose Morton code (interleaved keys)
    // is `code`, or the leaf above it (its depth in `reached`); unknown
    // space reads as a leaf with log-odds -infinity (OctreeView::
    // child_or_absent).  Starts from the deepest node the last walk in the
    // same root octant passed through that lies on this cube's path too.
    OctreeView::NodeRef node_of(uint64_t code, int depth, int &reached);
    bool beyond_reach(OctreeView::NodeRef node, const int32_t cube[3], int shift, const KeyRange &range) const;

    // The last walk down one child of the root.  A map centred on the
    // origin lies across all eight, so a walk from the root would follow
    // their long single-child chains again whenever a shape's cubes, or
    // the next shape's, are in another octant.
    struct Path {
        uint64_t code = 0;  // the Morton code the walk followed
        int depth = 0;      // nodes[0 .. depth] are its nodes
        OctreeView::NodeRef nodes[kTreeDepth + 1];
    };

    const OctreeView &view_;
    double cells_per_metre_;
    Path paths_[8];
};

}  // namespace octoprox
