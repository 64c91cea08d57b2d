// The self-collision broad phase's box test in lanes: the AVX2 and the
// portable loops give, bit for bit, what Aabb::overlaps says, for boxes
// that overlap, touch on a face or an edge, or miss by one rounding, over
// more entries than one 64-bit word holds and at every row and start;
// with a word of wanted entries, that test for the wanted ones alone.
#include "base/avx2.hpp"
#include "query/self/link_boxes.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

namespace {

using namespace octoprox;

// Boxes on a coarse lattice, so that faces coincide often; some moved by
// one rounding.
std::vector<Aabb> lattice_boxes(size_t count, unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> corner(0, 6), size(0, 3), nudge(0, 5);
    std::vector<Aabb> boxes(count);
    for (Aabb &box : boxes) {
        for (int axis = 0; axis < 3; ++axis) {
            box.lo[axis] = 0.25 * corner(random);
            box.hi[axis] = box.lo[axis] + 0.25 * size(random);
            if (nudge(random) == 0) box.lo[axis] = std::nextafter(box.lo[axis], 10.0);
        }
    }
    return boxes;
}

BoxRows rows_of(const std::vector<Aabb> &boxes) {
    BoxRows rows;
    const size_t padded = (boxes.size() + 3) / 4 * 4 + 4;
    for (int axis = 0; axis < 3; ++axis) {
        rows.lo[axis].assign(padded, std::numeric_limits<double>::infinity());
        rows.hi[axis].assign(padded, -std::numeric_limits<double>::infinity());
        for (size_t i = 0; i < boxes.size(); ++i) {
            rows.lo[axis][i] = boxes[i].lo[axis];
            rows.hi[axis][i] = boxes[i].hi[axis];
        }
    }
    return rows;
}

uint64_t expected_bits(const std::vector<Aabb> &boxes, size_t row, size_t first, size_t count) {
    uint64_t bits = 0;
    for (size_t k = 0; k < count; ++k)
        if (boxes[row].overlaps(boxes[first + k])) bits |= uint64_t{1} << k;
    return bits;
}

TEST(LinkBoxes, OverlapBitsAreTheBoxTest) {
    std::printf("tested by %s\n", cpu_has_avx2() ? "AVX2 lanes and the portable loop" : "the portable loop");
    for (unsigned seed = 1; seed <= 20; ++seed) {
        const std::vector<Aabb> boxes = lattice_boxes(70 + seed, seed);
        const BoxRows rows = rows_of(boxes);
        for (size_t row = 0; row < boxes.size(); ++row) {
            for (size_t first = 0; first < boxes.size(); first += 7) {
                const size_t count = std::min<size_t>(64, boxes.size() - first);
                const uint64_t expected = expected_bits(boxes, row, first, count);
                EXPECT_EQ(overlap_bits_portable(rows, row, first, count), expected) << row << " " << first;
                if (cpu_has_avx2()) {
                    EXPECT_EQ(overlap_bits_avx2(rows, row, first, count), expected) << row << " " << first;
                }
            }
        }
    }
}

TEST(LinkBoxes, PaddingOverlapsNothing) {
    const std::vector<Aabb> boxes = lattice_boxes(5, 3);
    const BoxRows rows = rows_of(boxes);
    for (size_t row = 0; row < boxes.size(); ++row)
        EXPECT_EQ(overlap_bits(rows, row, 0, 5), expected_bits(boxes, row, 0, 5));
}

TEST(LinkBoxes, OnlyWantedEntriesAreTested) {
    std::mt19937_64 random(5);
    for (unsigned seed = 1; seed <= 10; ++seed) {
        const std::vector<Aabb> boxes = lattice_boxes(90, seed);
        const BoxRows rows = rows_of(boxes);
        for (size_t row = 0; row < boxes.size(); ++row) {
            // Sparse words (whole runs of four unwanted), dense ones, none.
            const uint64_t a = random(), b = random();
            for (uint64_t wanted : {a & b & random(), a, uint64_t{0}, kEveryEntry, uint64_t{0xF0F0}}) {
                for (size_t first = 0; first < boxes.size(); first += 13) {
                    const size_t count = std::min<size_t>(64, boxes.size() - first);
                    const uint64_t expected = expected_bits(boxes, row, first, count) & wanted;
                    EXPECT_EQ(overlap_bits_portable(rows, row, first, count, wanted), expected) << row << " " << first;
                    if (cpu_has_avx2()) {
                        EXPECT_EQ(overlap_bits_avx2(rows, row, first, count, wanted), expected) << row << " " << first;
                    }
                }
            }
        }
    }
}

}  // namespace
