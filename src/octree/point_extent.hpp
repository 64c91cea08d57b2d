// Point extents: the box of the sensed points that fell in an occupied
// leaf, kept in the leaf's otherwise unused 4 bytes (bounded_tree.hpp).
//
// Inner nodes pack their obstacle boxes the same way (bounded_tree.hpp):
// per axis the first and last 1/32nd of the cube that holds a point (5
// bits each), and a validity bit; 0 means no extent (the whole cube is the
// obstacle).  Points become slots at the finest depth with a slack that
// the engines' decoding pad covers (point_slots.hpp), so the decoded box
// (obstacle_box in octree_cell.hpp) always holds every point recorded.
//
// Extents move between depths when OctoMap prunes eight equal leaves into
// their parent or expands a pruned leaf: a child's slot s lies in the
// parent's slot (s + 32 * side) / 2 (exact, no rounding), and a parent's
// slot p covers the child's slots 2 (p - 16 side) and the next one.
#pragma once

#include <algorithm>
#include <cstdint>

namespace octoprox {
namespace extent {

constexpr int kSlots = 32;
constexpr uint32_t kValid = 1u << 31;

inline bool valid(uint32_t packed) { return (packed & kValid) != 0; }
inline int lo(uint32_t packed, int axis) { return (packed >> (5 * axis)) & 31; }
inline int hi(uint32_t packed, int axis) { return (packed >> (15 + 5 * axis)) & 31; }

inline uint32_t pack(const int lo_slot[3], const int hi_slot[3]) {
    uint32_t packed = kValid;
    for (int axis = 0; axis < 3; ++axis) {
        packed |= static_cast<uint32_t>(lo_slot[axis]) << (5 * axis);
        packed |= static_cast<uint32_t>(hi_slot[axis]) << (15 + 5 * axis);
    }
    return packed;
}

// The union of two valid extents of one cube.
inline uint32_t merge(uint32_t a, uint32_t b) {
    int lo_slot[3], hi_slot[3];
    for (int axis = 0; axis < 3; ++axis) {
        lo_slot[axis] = std::min(lo(a, axis), lo(b, axis));
        hi_slot[axis] = std::max(hi(a, axis), hi(b, axis));
    }
    return pack(lo_slot, hi_slot);
}

// A valid extent of child `child` (x = bit 0) in its parent's slots.
inline uint32_t to_parent(uint32_t packed, int child) {
    int lo_slot[3], hi_slot[3];
    for (int axis = 0; axis < 3; ++axis) {
        const int side = ((child >> axis) & 1) * kSlots;
        lo_slot[axis] = (lo(packed, axis) + side) >> 1;
        hi_slot[axis] = (hi(packed, axis) + side) >> 1;
    }
    return pack(lo_slot, hi_slot);
}

// The part of a parent's valid extent inside child `child`, in the
// child's slots; 0 when the extent misses the child.
inline uint32_t to_child(uint32_t packed, int child) {
    int lo_slot[3], hi_slot[3];
    for (int axis = 0; axis < 3; ++axis) {
        const int offset = ((child >> axis) & 1) * (kSlots / 2);
        lo_slot[axis] = std::max(0, 2 * (lo(packed, axis) - offset));
        hi_slot[axis] = std::min(kSlots - 1, 2 * (hi(packed, axis) - offset) + 1);
        if (lo_slot[axis] > hi_slot[axis]) return 0;
    }
    return pack(lo_slot, hi_slot);
}

// A finest cell's valid extent in the slots of its ancestor `levels` up;
// `code` is the cell's Morton code (x in bit 0).
inline uint32_t lift(uint32_t packed, uint64_t code, int levels) {
    for (int level = 0; level < levels; ++level) packed = to_parent(packed, static_cast<int>((code >> (3 * level)) & 7));
    return packed;
}

}  // namespace extent

// One finest cell's extent in a frame: its Morton code and packed box.
struct CellExtent {
    uint64_t code = 0;
    uint32_t packed = 0;
};

}  // namespace octoprox
