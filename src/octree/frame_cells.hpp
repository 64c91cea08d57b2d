// The cells a frame updates, in the order a depth-first walk of the map
// meets them: a cell holding an
// endpoint updated as occupied and every other crossed cell as free (as
// OctoMap's computeUpdate, which removes endpoint cells from the free set).
#pragma once

#include "octree/frame_marks.hpp"
#include "octree/cell_range.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace octoprox {

// An allocator whose vectors leave elements they size uninitialised:
// collect_cells sizes the list, then writes every cell; zeroing the tens
// of megabytes of a large frame first would cost milliseconds.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
    template <class U>
    struct rebind {
        using other = UninitializedAllocator<U>;
    };
    UninitializedAllocator() = default;
    template <class U>
    UninitializedAllocator(const UninitializedAllocator<U> &) noexcept {}
    template <class U>
    void construct(U *at) noexcept {
        ::new (static_cast<void *>(at)) U;
    }
    template <class U, class... Args>
    void construct(U *at, Args &&...args) {
        ::new (static_cast<void *>(at)) U(std::forward<Args>(args)...);
    }
};

struct FrameCells {
    // Morton codes of finest-cell keys (x in bit 0), ascending, each once;
    // kHitBit set for occupied updates, kClearBit for cells set to the
    // free clamp (self-filtering's robot volume).
    static constexpr uint64_t kHitBit = uint64_t{1} << 63;
    static constexpr uint64_t kClearBit = uint64_t{1} << 62;
    std::vector<uint64_t, UninitializedAllocator<uint64_t>> cells;
    uint64_t hits = 0, misses = 0, cleared = 0;
    KeyBox box;  // keys of every cell

    static uint64_t code(uint64_t cell) { return cell & ~(kHitBit | kClearBit); }
    static bool is_hit(uint64_t cell) { return (cell & kHitBit) != 0; }
    static bool is_clear(uint64_t cell) { return (cell & kClearBit) != 0; }
};

// `extra` holds cells found outside the marks (Morton code, kHitBit for an
// endpoint), in any order, duplicates allowed.  Large frames are read out
// on up to `threads` threads (0: one per hardware thread).
FrameCells collect_cells(const FrameMarks &marks, std::vector<uint64_t> extra, size_t threads = 1);
// The same for cells found without marks alone.
FrameCells sorted_cells(std::vector<uint64_t> cells);
// Adds cells to set to the free clamp (Morton codes, any order, each
// once).  Such a cell replaces a miss of the same cell; a hit keeps its
// cell (no sensed point lies inside the robot).
void add_clear_cells(FrameCells &cells, const std::vector<uint64_t> &clear);
// Keeps the cells inside `bounds` alone, their counts and box recomputed.
void clip_cells(FrameCells &cells, const CellRange &bounds);

}  // namespace octoprox
