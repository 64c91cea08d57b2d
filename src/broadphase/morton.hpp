// Morton (z-order) codes of points quantized on a 2^k lattice (paper IV.A).
//
// A code interleaves the bits of the three quantized coordinates, x in bit
// 0, y in bit 1, z in bit 2 of every triple, most significant triple first;
// sorting by code lays points out along the z-order curve, and the codes'
// common prefixes are the cells of an implicit octree over the lattice.
#pragma once

#include "geometry/aabb.hpp"

#include <cstdint>

namespace octoprox {

// At most 21 bits per axis: 63 bits of code fit a uint64_t.
constexpr int kMaxMortonBits = 21;

// Spreads the low 21 bits of v so that bit i lands in bit 3i: the classic
// magic numbers, each step doubling the gaps between groups of bits (16,
// 8, 4, 2, 1 bits apart) until bits sit 3 apart.  Inline, as quantize
// below: the tree build calls both for every box.
inline uint64_t morton_spread(uint32_t v) {
    uint64_t x = v & 0x1FFFFFu;
    x = (x | (x << 32)) & 0x001F00000000FFFFull;
    x = (x | (x << 16)) & 0x001F0000FF0000FFull;
    x = (x | (x << 8)) & 0x100F00F00F00F00Full;
    x = (x | (x << 4)) & 0x10C30C30C30C30C3ull;
    x = (x | (x << 2)) & 0x1249249249249249ull;
    return x;
}
// The inverse of morton_spread: gathers bits 0, 3, 6, ... into the low 21 bits.
uint32_t morton_compact(uint64_t code);

inline uint64_t morton_encode(uint32_t x, uint32_t y, uint32_t z) {
    return morton_spread(x) | (morton_spread(y) << 1) | (morton_spread(z) << 2);
}
inline void morton_decode(uint64_t code, uint32_t &x, uint32_t &y, uint32_t &z) {
    x = morton_compact(code);
    y = morton_compact(code >> 1);
    z = morton_compact(code >> 2);
}

// Maps points of a bounding box onto the 2^bits lattice over it: cell
// floor((p - lo) / extent * 2^bits) per axis, clamped to [0, 2^bits - 1] so
// that the upper faces (and rounding) stay on the lattice.  A flat axis
// (zero extent) quantizes to 0.
class MortonQuantizer {
public:
    MortonQuantizer() = default;
    // bits is clamped to [1, kMaxMortonBits]; bounds must not be empty.
    MortonQuantizer(const Aabb &bounds, int bits);

    int bits() const { return bits_; }
    int code_bits() const { return 3 * bits_; }
    uint32_t quantize(double value, int axis) const {
        const double cell = (value - origin_[axis]) * scale_[axis];
        // Below 1 (NaN too) is cell 0; above, truncation is the floor, and
        // it needs no call into libm.
        if (!(cell >= 1.0)) return 0;
        if (cell >= static_cast<double>(max_cell_)) return max_cell_;
        return static_cast<uint32_t>(cell);
    }
    uint64_t encode(const Vec3 &point) const {
        return morton_encode(quantize(point.x(), 0), quantize(point.y(), 1), quantize(point.z(), 2));
    }

private:
    Vec3 origin_ = Vec3::Zero();
    Vec3 scale_ = Vec3::Zero();  // lattice cells per metre, 0 on a flat axis
    int bits_ = 1;
    uint32_t max_cell_ = 1;
};

}  // namespace octoprox
