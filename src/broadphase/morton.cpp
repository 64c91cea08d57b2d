#include "broadphase/morton.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {

uint32_t morton_compact(uint64_t code) {
    uint64_t x = code & 0x1249249249249249ull;
    x = (x | (x >> 2)) & 0x10C30C30C30C30C3ull;
    x = (x | (x >> 4)) & 0x100F00F00F00F00Full;
    x = (x | (x >> 8)) & 0x001F0000FF0000FFull;
    x = (x | (x >> 16)) & 0x001F00000000FFFFull;
    x = (x | (x >> 32)) & 0x1FFFFFull;
    return static_cast<uint32_t>(x);
}

MortonQuantizer::MortonQuantizer(const Aabb &bounds, int bits)
    : origin_(bounds.lo), bits_(std::clamp(bits, 1, kMaxMortonBits)) {
    max_cell_ = (uint32_t{1} << bits_) - 1;
    const double cells = static_cast<double>(uint32_t{1} << bits_);
    for (int axis = 0; axis < 3; ++axis) {
        const double extent = bounds.hi[axis] - bounds.lo[axis];
        scale_[axis] = extent > 0.0 ? cells / extent : 0.0;
    }
}


}  // namespace octoprox
