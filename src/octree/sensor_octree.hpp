// The sensor octree behind an opx_octree handle: OctoMap's occupancy octree
// (with obstacle boxes in its inner nodes, bounded_tree.hpp) and our parameters, the cell classes of the paper (occupied / uncertain / free /
// unknown) and sensor-frame insertion.
#pragma once

#include "geometry/aabb.hpp"
#include "octree/frame_marks.hpp"
#include "octree/cell_range.hpp"
#include "geometry/pose.hpp"
#include "octree/octree_params.hpp"
#include "octree/obstacle_grid_cache.hpp"
#include "octree/octree_view.hpp"
#include "octree/ray_clip.hpp"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace octoprox {

class BoundedOcTree;
class CubeRegion;
struct EditedCubes;

enum CellClass : int { kUnknown = 0, kFree = 1, kUncertain = 2, kOccupied = 3 };

// Strided points of 3 float32 or float64 coordinates, read unaligned.
struct PointSource {
    const unsigned char *data = nullptr;
    size_t count = 0;
    size_t stride = 0;  // bytes, never 0 here
    bool is_double = false;

    Vec3 read(size_t index) const {
        const unsigned char *at = data + index * stride;
        if (is_double) {
            double xyz[3];
            std::memcpy(xyz, at, sizeof xyz);
            return Vec3(xyz[0], xyz[1], xyz[2]);
        }
        float xyz[3];
        std::memcpy(xyz, at, sizeof xyz);
        return Vec3(xyz[0], xyz[1], xyz[2]);
    }
};

struct InsertSettings {
    bool raycast = true;
    Pose sensor_pose;
    double max_range = -1.0;  // <= 0 or infinite: no limit
    uint32_t max_threads = 1;  // 0: one per hardware thread
    // Rays cut short (the robot in its own frame); nullptr: none.  Its
    // origin is sensor_pose's translation.
    const RayClip *clip = nullptr;
    // Finest cells set to the free clamp in the same update (Morton codes
    // of their keys, any order, each once); nullptr: none.
    const std::vector<uint64_t> *clear_cells = nullptr;
    // Only cells inside change (their counts alone are reported); nullptr:
    // the whole map.
    const CellRange *bounds = nullptr;
};

struct InsertCounts {
    uint64_t used = 0, nonfinite = 0, out_of_range = 0, outside_map = 0;
    uint64_t on_robot = 0, shadowed = 0;
    uint64_t cells_hit = 0, cells_missed = 0, cells_cleared = 0;
};

struct CellInfo {
    int cell_class = kUnknown;
    double probability = 0.5;
    double center[3] = {0, 0, 0};
    double size = 0;
    int depth = 0;
};

struct TreeStats {
    uint64_t leaves[4] = {0, 0, 0, 0};  // by CellClass
    uint64_t inner_nodes = 0;
    uint64_t memory_bytes = 0;
    bool has_occupied = false, has_known = false;
    double occupied_min[3] = {0, 0, 0}, occupied_max[3] = {0, 0, 0};
    double known_min[3] = {0, 0, 0}, known_max[3] = {0, 0, 0};
    uint64_t leaves_with_extent = 0;  // occupied leaves keeping a point extent
};

class SensorOctree {
public:
    explicit SensorOctree(const OctreeParams &params);
    // Adopts a tree read from a file; params.resolution must be its resolution.
    // Its inner nodes are recomputed (values and obstacle boxes).
    SensorOctree(const OctreeParams &params, std::unique_ptr<BoundedOcTree> tree);
    ~SensorOctree();

    const OctreeParams &params() const { return params_; }
    OctreeView view() const { return OctreeView(tree_.get(), occupied_log_odds_); }
    const BoundedOcTree &octomap_tree() const { return *tree_; }

    int classify_log_odds(float log_odds) const {
        if (log_odds >= occupied_log_odds_) return kOccupied;
        return log_odds < free_log_odds_ ? kFree : kUncertain;
    }
    // True when the point (map frame) lies inside the addressable cube.
    bool contains(const Vec3 &point) const;

    InsertCounts insert(const PointSource &points, const InsertSettings &settings);
    CellInfo classify(const Vec3 &point) const;  // point inside the cube
    TreeStats stats() const;
    void clear();
    // Every cell of the region (region_edit.hpp) set to the free clamp, or
    // removed (unknown).  All or nothing: throws std::bad_alloc, changing
    // nothing, when the blocks the edit needs cannot be had.
    void clear_region(const CubeRegion &region, bool to_free);
    // Every known cell's log-odds toward 0 by amount (> 0; decay.hpp).
    void decay(double amount);
    // Every cell outside `keep` removed; the pool then gives its idle
    // memory back to the heap when it holds more than a quarter idle.
    void crop(const CellRange &keep);
    // Bounds of every observed cell, kept up to date by each change, so
    // queries can bound unknown space without a pass over the map.
    const Aabb &known_bounds() const { return known_bounds_; }
    // Every leaf's point extent (0: none), depth first, children by index;
    // set_leaf_extents gives them back (false, nothing set, when the count
    // is not the map's leaf count).  For OctoProx map files.
    std::vector<uint32_t> leaf_extents() const;
    bool set_leaf_extents(const std::vector<uint32_t> &extents);
    // A process-unique identity and a count of changes: a query context
    // that built structures from this map rebuilds them when either moved.
    uint64_t identity() const { return identity_; }
    uint64_t generation() const { return generation_; }
    // The obstacle leaves at or above `threshold` as a grid
    // (obstacle_grid.hpp), built on the first request for this state of
    // the map and shared by every caller; nullptr when the map's obstacles
    // span too large a box.  Thread-safe, as const calls are.
    std::shared_ptr<const ObstacleGrid> obstacle_grid(float threshold) const {
        return grid_cache_.get(view(), generation_, threshold);
    }

private:
    void apply_params();
    void grow_known_bounds(const KeyBox &keys);
    void recompute_known_bounds();
    void update_known_bounds(const EditedCubes &edited);

    OctreeParams params_;
    std::unique_ptr<BoundedOcTree> tree_;
    // Thresholds as float log-odds, compared with the stored float log-odds
    // exactly as OctoMap's isNodeOccupied does.
    float occupied_log_odds_ = 0.0f;
    float free_log_odds_ = 0.0f;
    Aabb known_bounds_;
    uint64_t identity_ = next_identity();
    uint64_t generation_ = 0;
    ObstacleGridCache grid_cache_;
    static uint64_t next_identity();
};

}  // namespace octoprox
