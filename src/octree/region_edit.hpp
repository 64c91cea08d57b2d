// Changing every cell of a region of the map at once: clearing (to free or
// to unknown), cropping, and the region tests they take.
//
// A region says of any cube of the tree whether all, none or part of its
// finest cells lie in it; a finest cell is always all or none.  The edit
// walks the map from the root and stops where a cube is all or none, so a
// large region costs the cubes along its boundary, not its volume: a
// pruned leaf is expanded only where the boundary crosses it, a subtree
// wholly inside is removed or set in one step, and every node on a changed
// path is pruned or has its occupancy (and obstacle box) recomputed on the
// way up, as an update by OctoMap's updateNode would leave it.
#pragma once

#include "octree/cell_range.hpp"
#include "octree/octree_view.hpp"

#include <cstddef>
#include <cstdint>

namespace octoprox {

class BoundedOcTree;
class BoundedNode;

enum class Cover { kNone, kAll, kPart };

class CubeRegion {
public:
    virtual ~CubeRegion() = default;
    // kPart may be answered for a cube none of whose finest cells is in
    // the region (a conservative test); never for a finest cell.
    virtual Cover cover(const CellKey &cube) const = 0;
};

// The finest cells of a key range, or (outside) every other cell.
class CellRangeRegion : public CubeRegion {
public:
    CellRangeRegion(const CellRange &range, bool outside) : range_(range), outside_(outside) {}
    Cover cover(const CellKey &cube) const override {
        const Cover inside = range_.holds_cube(cube) ? Cover::kAll : range_.meets_cube(cube) ? Cover::kPart : Cover::kNone;
        if (!outside_ || inside == Cover::kPart) return inside;
        return inside == Cover::kAll ? Cover::kNone : Cover::kAll;
    }

private:
    CellRange range_;
    bool outside_;
};

struct RegionEdit {
    bool to_free = false;    // cells become free (log-odds free_value), else unknown
    float free_value = 0.0f; // the free clamp
};

// What an edit changed: the keys of the cubes it removed and of those it
// set free (each empty when none), for the map's known bounds.
struct EditedCubes {
    CellRange removed;
    CellRange set_free;
    bool changed = false;
};

// The child blocks the edit will take from the pool (expanded pruned
// leaves, new nodes of free space): reserve them before editing, so that
// an edit that runs out of memory fails before it starts.
size_t region_edit_blocks(const BoundedOcTree &tree, const CubeRegion &region, const RegionEdit &edit);

// The blocks the map holds after removing the cells of a region whose
// kPart answers are exact (a CellRange region): for a crop, which moves
// them into fresh slabs reserved before it starts.
size_t blocks_after_removal(const BoundedOcTree &tree, const CubeRegion &region);

// Call inside a BoundsScope, with the blocks reserved.
EditedCubes apply_region_edit(BoundedOcTree &tree, const CubeRegion &region, const RegionEdit &edit);

}  // namespace octoprox
