// A sensed point's slots in its finest cell (point_extent.hpp packs
// them): what the insert records of every endpoint.
#pragma once

#include "octree/octree_view.hpp"
#include "octree/point_extent.hpp"

#include <cstdint>

namespace octoprox {
namespace extent {

// A point's slots in a finest cell, per axis: the slot of the point moved
// down and up by kSlack slots.  The slack is far above the rounding of
// the arithmetic here (coordinates within 2^15 cells of the origin:
// ~1e-10 slots) and far below the padding the engines decode a box with
// (obstacle_box_pad: ~1e-6 slots), so the decoded box holds the point.  A
// point just outside the cell (rounding of its key) takes the face slot.
class PointSlots {
public:
    explicit PointSlots(double resolution) : resolution_(resolution), per_metre_(kSlots / resolution) {}

    // key: the cell's integer key on the axis; coordinate: the point's.
    void of(uint16_t key, double coordinate, int &lo_slot, int &hi_slot) const {
        const double cell_lo = static_cast<double>(static_cast<int32_t>(key) - kKeyCenter) * resolution_;
        const double t = (coordinate - cell_lo) * per_metre_;
        lo_slot = clamp(static_cast<int>(t - kSlack));
        hi_slot = clamp(static_cast<int>(t + kSlack));
    }

private:
    static constexpr double kSlack = 1e-7;
    static int clamp(int s) { return s < 0 ? 0 : (s > kSlots - 1 ? kSlots - 1 : s); }
    double resolution_, per_metre_;
};

}  // namespace extent
}  // namespace octoprox
