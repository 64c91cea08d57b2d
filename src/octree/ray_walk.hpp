// Stepping rays through the map's cells, cell for cell the ones OctoMap's
// computeRayKeys returns (Amanatides & Woo's 3-D DDA with OctoMap's float
// and double arithmetic and its order of comparisons, so ties between
// axes and rays along faces, axes and diagonals go the same way), marked
// in a FrameMarks instead of collected in a list.
#pragma once

#include "octree/frame_marks.hpp"
#include "octree/ray_setup.hpp"

#include <octomap/OcTreeKey.h>
#include <octomap/octomap_types.h>

#include <vector>

namespace octoprox {

class BoundedOcTree;

// How many rays a walk steps at once: four needs AVX2 (cpu_has_avx2,
// base/avx2.hpp) and falls back to two without it; the best is four where
// the processor has it.  Every choice marks the same cells.
enum class RayLanes { kBest, kTwo, kFour };

class RayWalker {
public:
    // The origin must lie inside the map; origin_key is its key.
    RayWalker(const BoundedOcTree &tree, const octomap::point3d &origin, const octomap::OcTreeKey &origin_key);

    // Marks as crossed, for rays [begin, end) of `ends`, the cells from the
    // origin's cell up to, not including, the end's cell (`end_keys` the
    // ends' keys).  A ray that might leave the marks' box (along the map's
    // outer faces) is not walked: its index goes to `strays`, for OctoMap's
    // computeRayKeys.
    void walk(const std::vector<octomap::point3d> &ends, const std::vector<octomap::OcTreeKey> &end_keys,
              size_t begin, size_t end, FrameMarks &marks, std::vector<uint32_t> &strays,
              RayLanes lanes = RayLanes::kBest) const;

private:
    RayOrigin origin_;
    octomap::OcTreeKey origin_key_;
};

}  // namespace octoprox
