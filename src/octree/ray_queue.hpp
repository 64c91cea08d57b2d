// The rays of one range of a frame, set up one after another for the
// lanes of a ray walk (ray_walk.cpp, ray_walk_avx2.cpp): OctoMap's face
// parameters and the moves of the ray's bit in the marks.
#pragma once

#include "octree/frame_marks.hpp"
#include "octree/ray_setup.hpp"

#include <octomap/OcTreeKey.h>
#include <octomap/octomap_types.h>

#include <cstdint>
#include <vector>

namespace octoprox {

// One ray's place in the marks.  Inside the box a key and its bit
// determine each other, so the bit alone is stepped and compared.
struct LaneRay {
    uint64_t bit = 0, last_bit = 0;
    BitMoves moves{};

    // One step along `axis`; false once the ray is done.
    bool step(int axis, bool past_end) {
        const uint64_t leaves_brick = uint64_t{0} - ((bit & moves.edge_mask[axis]) == moves.edge_value[axis]);
        bit += moves.in_brick[axis] + static_cast<int64_t>(leaves_brick & moves.brick_change[axis]);
        // The end's cell is not marked; past the end point without meeting
        // it (rounding) the ray is done too.
        return bit != last_bit && !past_end;
    }
};

// The rays of one range, handed to the lanes one after another.
class RayQueue {
public:
    RayQueue(const RayOrigin &origin, const octomap::OcTreeKey &origin_key,
             const std::vector<octomap::point3d> &ends, const std::vector<octomap::OcTreeKey> &end_keys,
             size_t begin, size_t end, FrameMarks &marks, std::vector<uint32_t> &strays)
        : origin_(origin), origin_key_(origin_key), ends_(ends), end_keys_(end_keys), next_(begin), end_(end),
          marks_(marks), strays_(strays) {
        for (int i = 0; i < 3; ++i) origin_cell_[i] = origin_key[i];
        last_end_key_ = origin_key;
        origin_inside_ = marks.holds(origin_cell_, kOriginMargin);
        origin_bit_ = origin_inside_ ? marks.bit_of(origin_cell_) : 0;
        const int down[3] = {-1, -1, -1}, up[3] = {1, 1, 1};
        moves_[0] = bit_moves(down, marks);
        moves_[1] = bit_moves(up, marks);
    }

    // The next ray with cells to walk, false when none is left.
    bool next(LaneRay &ray, RaySetup &setup) {
        size_t index;
        if (!next_index(index)) return false;
        setup = ray_setup(origin_, ends_[index]);
        start(index, setup, ray);
        return true;
    }

    // The index of the next ray with cells to walk, false when none is
    // left.  Rays inside the origin's cell are skipped, rays that might
    // leave the marks go to the strays.
    bool next_index(size_t &index) {
        while (next_ < end_) {
            index = next_++;
            const octomap::OcTreeKey &key = end_keys_[index];
            if (key == origin_key_) continue;  // inside the origin's cell: no cell to free
            const uint32_t end_cell[3] = {key[0], key[1], key[2]};
            if (origin_inside_ && marks_.holds(end_cell, kEndMargin)) return true;
            strays_.push_back(static_cast<uint32_t>(index));
        }
        return false;
    }

    // Starts ray `index` in the origin's cell, which it marks.
    void start(size_t index, const RaySetup &setup, LaneRay &ray) {
        for (int axis = 0; axis < 3; ++axis) {  // an axis without steps is never chosen
            const BitMoves &m = moves_[setup.step[axis] > 0];
            ray.moves.in_brick[axis] = m.in_brick[axis];
            ray.moves.brick_change[axis] = m.brick_change[axis];
            ray.moves.edge_mask[axis] = m.edge_mask[axis];
            ray.moves.edge_value[axis] = m.edge_value[axis];
        }
        ray.bit = origin_bit_;
        ray.last_bit = end_bit(index);
        marks_.mark_crossed(origin_bit_);
    }

    // The bit of ray `index`'s end cell, where its walk stops.
    uint64_t end_bit(size_t index) {
        const octomap::OcTreeKey &key = end_keys_[index];
        // Neighbouring rays mostly end in one cell: its bit is kept.
        if (!(key == last_end_key_)) {
            const uint32_t end_cell[3] = {key[0], key[1], key[2]};
            last_end_key_ = key;
            last_end_bit_ = marks_.bit_of(end_cell);
        }
        return last_end_bit_;
    }

    const RayOrigin &origin() const { return origin_; }
    const octomap::point3d &end_point(size_t index) const { return ends_[index]; }

    // The origin's cell, marked as soon as a ray is handed out.
    uint64_t origin_bit() const { return origin_bit_; }

private:
    // Where a walk can go.  The first step moves one cell from the
    // origin's cell.  Every later step crosses a face whose parameter was
    // at most the ray's length: a face at most a rounding error (far below
    // a cell, even for a ray across the whole map) beyond the end point,
    // so into a cell at most one past the end's cell on that axis.  The
    // margins below leave one more cell of slack; a ray without them (the
    // frame's box is cut by the map's outer faces) takes OctoMap's way.
    static constexpr uint32_t kOriginMargin = 2;
    static constexpr uint32_t kEndMargin = 2;

    const RayOrigin &origin_;
    const octomap::OcTreeKey origin_key_;
    uint32_t origin_cell_[3];
    bool origin_inside_ = false;
    BitMoves moves_[2];  // every axis stepping down, up
    uint64_t origin_bit_ = 0;
    // The end cell of the last ray started and its bit; the origin's cell
    // at first, which no started ray ends in.
    octomap::OcTreeKey last_end_key_;
    uint64_t last_end_bit_ = 0;
    const std::vector<octomap::point3d> &ends_;
    const std::vector<octomap::OcTreeKey> &end_keys_;
    size_t next_;
    const size_t end_;
    FrameMarks &marks_;
    std::vector<uint32_t> &strays_;
};

// Walks the queue's rays four at a time with AVX2; only where
// cpu_has_avx2() (base/avx2.hpp) says so.
void walk_four(RayQueue &queue, FrameMarks &marks);

}  // namespace octoprox
