// The cells one sensor frame touches, as two marks per cell (crossed by a
// ray, holds an endpoint): bitmaps over the frame's box of keys, grown to
// whole bricks of 8x8x8 cells.
//
// A ray-cast frame steps through millions of cells but touches far fewer
// distinct ones, as rays from one origin cross the same cells near the
// sensor.  OctoMap inserts every step into a hash set; here a step is one
// OR into a bit.  Two layouts:
//   - bricks, for large boxes: within a brick a step moves the bit by 1, 8
//     or 64, and a brick is 64 bytes, so a ray stays in a cache line for
//     several steps;
//   - rows of cells along x, for boxes whose marks fit a core's caches
//     (at most kRowsMaxCells): a step moves the bit by the same amount
//     wherever it is, which saves the walk the test for a brick's edge.
// A brick is the subtree of the map 3 levels above the leaves: the cells
// are read out brick by brick (brick_words), in either layout, which is
// how frame_cells.hpp gives them in the map's depth-first order.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace octoprox {

// A box of finest-cell keys, bounds included.
struct KeyBox {
    uint32_t lo[3] = {0, 0, 0};
    uint32_t hi[3] = {0, 0, 0};
    bool empty = true;

    void grow(const uint32_t key[3]) {
        for (int axis = 0; axis < 3; ++axis) {
            lo[axis] = empty ? key[axis] : std::min(lo[axis], key[axis]);
            hi[axis] = empty ? key[axis] : std::max(hi[axis], key[axis]);
        }
        empty = false;
    }
    void grow(const KeyBox &other);
    // Widened by `cells` on every side, kept within OctoMap's key range.
    KeyBox padded(uint32_t cells) const;
    // Cells inside, 0 when empty.
    uint64_t volume() const;
};

namespace brick {
constexpr int kShift = 3;  // 8 cells per axis
constexpr uint32_t kMask = 7;
constexpr int kBits = 512;
constexpr int kWords = kBits / 64;
}  // namespace brick

class FrameMarks {
public:
    // kBest: rows up to kRowsMaxCells, else bricks.  Every layout gives the
    // same cells.
    enum class Layout { kBest, kBricks, kRows };

    // Covers `box` (grown outwards to whole bricks) with crossed marks, all
    // cleared.  Throws std::bad_alloc when the bitmap does not fit in memory.
    void reset(const KeyBox &box, Layout layout = Layout::kBest);
    // Adds the endpoint marks, cleared, over the same box: only the marks
    // the frame's cells are read from need them (one per frame, not one
    // per thread).  Throws std::bad_alloc as reset.
    void add_endpoint_marks();
    // The most cells a box may hold (128 MiB a bitmap, mostly untouched);
    // larger frames take another way.
    static constexpr uint64_t kMaxCells = uint64_t{1} << 30;
    // The most cells of a box laid out in rows (512 KiB a bitmap).
    static constexpr uint64_t kRowsMaxCells = uint64_t{1} << 22;

    // Whether the bits run in rows along x (else brick after brick).
    bool in_rows() const { return in_rows_; }

    // Bit position of a key inside the box: in rows, x + X (y + Y z) for a
    // box of X by Y by Z cells; in bricks, the brick's index times 512 plus
    // x + 8 y + 64 z inside the brick.
    uint64_t bit_of(const uint32_t key[3]) const {
        if (in_rows_)
            return (key[0] - lo_[0]) + cell_stride_[1] * (key[1] - lo_[1]) + cell_stride_[2] * (key[2] - lo_[2]);
        uint64_t brick_index = 0, local = 0;
        for (int axis = 2; axis >= 0; --axis) {
            const uint32_t k = key[axis] - lo_[axis];
            brick_index = brick_index * bricks_[axis] + (k >> brick::kShift);
            local = (local << brick::kShift) | (k & brick::kMask);
        }
        return brick_index * brick::kBits + local;
    }
    // Whether `key` lies inside the box with `margin` cells to spare on
    // every side.
    bool holds(const uint32_t key[3], uint32_t margin) const {
        for (int axis = 0; axis < 3; ++axis) {
            const uint32_t k = key[axis] - lo_[axis];  // wraps below the box
            if (k < margin || k + margin >= (bricks_[axis] << brick::kShift)) return false;
        }
        return true;
    }
    // How a bit position moves when a key steps +1 along `axis` inside its
    // brick, and when it steps into the next brick (in rows, 8 steps).
    int64_t unit_step(int axis) const {
        return in_rows_ ? cell_stride_[axis] : int64_t{1} << (brick::kShift * axis);
    }
    int64_t brick_step(int axis) const {
        return in_rows_ ? cell_stride_[axis] * 8 : brick_stride_[axis] * brick::kBits;
    }

    // ORs another frame's crossed marks over the same box into these.
    void merge_crossed(const FrameMarks &other);

    // Most steps cross a cell some ray has crossed already, often one the
    // previous step of another lane wrote: reading first and writing only a
    // new mark keeps those steps off a chain of stores to one word.
    void mark_crossed(uint64_t bit) {
        uint64_t &word = crossed_[bit >> 6];
        const uint64_t mark = uint64_t{1} << (bit & 63);
        if ((word & mark) == 0) word |= mark;
    }
    // After add_endpoint_marks.
    void mark_endpoint(uint64_t bit) { endpoint_[bit >> 6] |= uint64_t{1} << (bit & 63); }

    const uint32_t *lowest_key() const { return lo_; }  // the first brick's lowest corner
    const uint32_t *bricks_per_axis() const { return bricks_; }
    size_t brick_count() const { return static_cast<size_t>(bricks_[0]) * bricks_[1] * bricks_[2]; }
    // A brick's (x + X (y + Y z) in bricks) marks in brick order, x + 8 y +
    // 64 z: the crossed marks, and the endpoint marks (after
    // add_endpoint_marks).
    void crossed_brick(size_t brick_index, uint64_t out[brick::kWords]) const {
        brick_words(crossed_.get(), brick_index, out);
    }
    void endpoint_brick(size_t brick_index, uint64_t out[brick::kWords]) const {
        brick_words(endpoint_.get(), brick_index, out);
    }

private:
    void brick_words(const uint64_t *marks, size_t brick_index, uint64_t out[brick::kWords]) const;

    uint32_t lo_[3] = {0, 0, 0};
    uint32_t bricks_[3] = {0, 0, 0};
    int64_t brick_stride_[3] = {0, 0, 0};
    bool in_rows_ = false;
    int64_t cell_stride_[3] = {0, 0, 0};  // in rows: 1, X, X Y
    // calloc'd: a large box costs memory only where rays pass (the kernel
    // hands out zeroed pages on first touch).
    struct FreeWords {
        void operator()(uint64_t *words) const;
    };
    static std::unique_ptr<uint64_t[], FreeWords> cleared_words(size_t words);
    std::unique_ptr<uint64_t[], FreeWords> crossed_, endpoint_;
    size_t words_ = 0;
};

}  // namespace octoprox
