// Morton codes: bit interleaving against a bit-by-bit reference, round
// trips, order along the curve, and quantization onto the lattice.
#include "broadphase/morton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using octoprox::Aabb;
using octoprox::MortonQuantizer;
using octoprox::Vec3;

namespace {

// Bit i of x goes to bit 3i, of y to 3i + 1, of z to 3i + 2.
uint64_t reference_encode(uint32_t x, uint32_t y, uint32_t z, int bits) {
    uint64_t code = 0;
    for (int i = 0; i < bits; ++i) {
        code |= uint64_t((x >> i) & 1) << (3 * i);
        code |= uint64_t((y >> i) & 1) << (3 * i + 1);
        code |= uint64_t((z >> i) & 1) << (3 * i + 2);
    }
    return code;
}

}  // namespace

TEST(Morton, EncodeMatchesBitByBitReference) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<uint32_t> coordinate(0, (1u << 21) - 1);
    for (int i = 0; i < 100000; ++i) {
        const uint32_t x = coordinate(rng), y = coordinate(rng), z = coordinate(rng);
        ASSERT_EQ(octoprox::morton_encode(x, y, z), reference_encode(x, y, z, 21)) << x << " " << y << " " << z;
    }
    const uint32_t all = (1u << 21) - 1;
    EXPECT_EQ(octoprox::morton_encode(all, all, all), (uint64_t{1} << 63) - 1);
    EXPECT_EQ(octoprox::morton_encode(1, 0, 0), 1u);
    EXPECT_EQ(octoprox::morton_encode(0, 1, 0), 2u);
    EXPECT_EQ(octoprox::morton_encode(0, 0, 1), 4u);
    // Bits above 21 are ignored.
    EXPECT_EQ(octoprox::morton_encode(all + 1, 0, 0), 0u);
}

TEST(Morton, DecodeInvertsEncode) {
    std::mt19937_64 rng(8);
    std::uniform_int_distribution<uint32_t> coordinate(0, (1u << 21) - 1);
    for (int i = 0; i < 100000; ++i) {
        const uint32_t x = coordinate(rng), y = coordinate(rng), z = coordinate(rng);
        uint32_t dx, dy, dz;
        octoprox::morton_decode(octoprox::morton_encode(x, y, z), dx, dy, dz);
        ASSERT_EQ(dx, x);
        ASSERT_EQ(dy, y);
        ASSERT_EQ(dz, z);
    }
}

// The code's top triples are the octants of an implicit octree: points in
// the lower half of every axis come before points in any other octant.
TEST(Morton, OrderFollowsOctants) {
    const uint32_t half = 1u << 20;
    const uint64_t low_corner = octoprox::morton_encode(half - 1, half - 1, half - 1);
    EXPECT_LT(low_corner, octoprox::morton_encode(half, 0, 0));
    EXPECT_LT(octoprox::morton_encode(half, half - 1, half - 1), octoprox::morton_encode(0, half, 0));
    EXPECT_LT(octoprox::morton_encode(half - 1, half, half - 1), octoprox::morton_encode(0, 0, half));
}

TEST(Morton, QuantizerCoversTheLattice) {
    const Aabb bounds{Vec3(-1.0, 0.0, 10.0), Vec3(3.0, 8.0, 10.0)};  // flat in z
    for (int bits : {1, 4, 10, 21}) {
        const MortonQuantizer q(bounds, bits);
        const uint32_t top = (1u << bits) - 1;
        EXPECT_EQ(q.bits(), bits);
        EXPECT_EQ(q.code_bits(), 3 * bits);
        EXPECT_EQ(q.quantize(-1.0, 0), 0u);
        EXPECT_EQ(q.quantize(3.0, 0), top) << "upper face stays on the lattice";
        EXPECT_EQ(q.quantize(-5.0, 0), 0u) << "below clamps";
        EXPECT_EQ(q.quantize(50.0, 1), top) << "above clamps";
        EXPECT_EQ(q.quantize(10.0, 2), 0u) << "flat axis";
        EXPECT_EQ(q.quantize(std::nan(""), 0), 0u);
        // The midpoint starts the upper half of the lattice.
        EXPECT_EQ(q.quantize(1.0, 0), (top + 1) / 2);
        EXPECT_EQ(q.quantize(1.0 - 1e-9, 0), (top + 1) / 2 - 1);
        const uint64_t code = q.encode(Vec3(3.0, 8.0, 10.0));
        EXPECT_EQ(code, octoprox::morton_encode(top, top, 0));
    }
    EXPECT_EQ(MortonQuantizer(bounds, 40).bits(), octoprox::kMaxMortonBits);
    EXPECT_EQ(MortonQuantizer(bounds, 0).bits(), 1);
}

// Quantization is monotone: a larger coordinate never gets a smaller cell.
TEST(Morton, QuantizerIsMonotone) {
    const Aabb bounds{Vec3(-20.0, -20.0, -20.0), Vec3(20.0, 20.0, 20.0)};
    const MortonQuantizer q(bounds, 10);
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> v(-21.0, 21.0);
    for (int i = 0; i < 100000; ++i) {
        double a = v(rng), b = v(rng);
        if (a > b) std::swap(a, b);
        ASSERT_LE(q.quantize(a, 0), q.quantize(b, 0)) << a << " " << b;
    }
}
