// The obstacle grid (obstacle_grid.hpp) a map keeps for its current state.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>

namespace octoprox {

class ObstacleGrid;
class OctreeView;

// One map's grid for the last threshold asked, rebuilt when the map's
// generation moved.  get() may run from several threads at once (const
// calls of the C ABI); a copy or move starts empty.
class ObstacleGridCache {
public:
    ObstacleGridCache() = default;
    ObstacleGridCache(const ObstacleGridCache &) {}
    ObstacleGridCache &operator=(const ObstacleGridCache &) { return *this; }

    std::shared_ptr<const ObstacleGrid> get(const OctreeView &view, uint64_t generation, float threshold) const;

private:
    mutable std::mutex mutex_;
    mutable std::shared_ptr<const ObstacleGrid> grid_;
    mutable bool built_ = false;  // grid_ (nullptr: too large) is for these:
    mutable uint64_t generation_ = 0;
    mutable float threshold_ = 0.0f;
};

}  // namespace octoprox
