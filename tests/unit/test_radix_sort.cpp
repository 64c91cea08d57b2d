// The radix sort against std::sort on (key, payload) pairs: random keys of
// every width and adversarial inputs, both digit sizes, reused scratch.
#include "broadphase/radix_sort.hpp"

#include "alloc_counter.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>

using octoprox::RadixScratch;
using octoprox::RadixSortOptions;

namespace {

// Sorts keys with payloads 0..n-1 both ways and compares.  Stability makes
// the radix order equal std::sort's on pairs (ties broken by payload).
void expect_sorted_like_std(const std::vector<uint64_t> &input, int key_bits, int digit_bits,
                            RadixScratch &scratch, const char *what) {
    std::vector<std::pair<uint64_t, uint32_t>> expected(input.size());
    for (size_t i = 0; i < input.size(); ++i) expected[i] = {input[i], static_cast<uint32_t>(i)};
    std::sort(expected.begin(), expected.end());

    std::vector<uint64_t> keys = input;
    std::vector<uint32_t> values(input.size());
    std::iota(values.begin(), values.end(), 0u);
    RadixSortOptions options;
    options.key_bits = key_bits;
    options.digit_bits = digit_bits;
    octoprox::radix_sort(keys, values, scratch, options);

    ASSERT_EQ(keys.size(), input.size());
    ASSERT_EQ(values.size(), input.size());
    for (size_t i = 0; i < input.size(); ++i) {
        ASSERT_EQ(keys[i], expected[i].first) << what << ", key_bits " << key_bits << ", digit "
                                              << digit_bits << ", at " << i;
        ASSERT_EQ(values[i], expected[i].second) << what << ", key_bits " << key_bits << ", digit "
                                                 << digit_bits << ", at " << i;
    }
}

std::vector<uint64_t> random_keys(size_t n, int key_bits, std::mt19937_64 &rng) {
    const uint64_t mask = key_bits == 64 ? ~uint64_t{0} : (uint64_t{1} << key_bits) - 1;
    std::vector<uint64_t> keys(n);
    for (uint64_t &k : keys) k = rng() & mask;
    return keys;
}

const int kDigitSizes[] = {8, 11};

}  // namespace

TEST(RadixSort, RandomKeysOfEveryWidth) {
    std::mt19937_64 rng(1);
    RadixScratch scratch;
    for (int key_bits : {1, 3, 8, 11, 12, 30, 33, 63, 64})
        for (int digit_bits : kDigitSizes)
            for (size_t n : {size_t{0}, size_t{1}, size_t{2}, size_t{7}, size_t{1000}, size_t{100000}})
                expect_sorted_like_std(random_keys(n, key_bits, rng), key_bits, digit_bits, scratch, "random");
}

TEST(RadixSort, AdversarialKeys) {
    std::mt19937_64 rng(2);
    RadixScratch scratch;
    const size_t n = 50000;
    for (int digit_bits : kDigitSizes) {
        expect_sorted_like_std(std::vector<uint64_t>(n, 0), 63, digit_bits, scratch, "all zero");
        expect_sorted_like_std(std::vector<uint64_t>(n, 0x5A5A5A5A5A5A5A5Aull), 63, digit_bits, scratch,
                               "all equal");
        std::vector<uint64_t> sorted = random_keys(n, 63, rng);
        std::sort(sorted.begin(), sorted.end());
        expect_sorted_like_std(sorted, 63, digit_bits, scratch, "sorted");
        std::vector<uint64_t> reversed(sorted.rbegin(), sorted.rend());
        expect_sorted_like_std(reversed, 63, digit_bits, scratch, "reversed");
        std::vector<uint64_t> duplicates = random_keys(n, 63, rng);
        for (uint64_t &k : duplicates) k = duplicates[k % 17];  // 17 distinct values
        expect_sorted_like_std(duplicates, 63, digit_bits, scratch, "duplicates");
        std::vector<uint64_t> two(n);
        for (size_t i = 0; i < n; ++i) two[i] = (i % 2) ? (uint64_t{1} << 62) : 1;
        expect_sorted_like_std(two, 63, digit_bits, scratch, "two values far apart");
        std::vector<uint64_t> sawtooth(n);
        for (size_t i = 0; i < n; ++i) sawtooth[i] = (n - i) % 1000;
        expect_sorted_like_std(sawtooth, 63, digit_bits, scratch, "sawtooth");
        std::vector<uint64_t> high_only(n);
        for (size_t i = 0; i < n; ++i) high_only[i] = (rng() % 4) << 60;  // only the last digit varies
        expect_sorted_like_std(high_only, 63, digit_bits, scratch, "top digit only");
        std::vector<uint64_t> extremes(n);
        for (size_t i = 0; i < n; ++i) extremes[i] = (i % 3 == 0) ? ~uint64_t{0} : (i % 3 == 1 ? 0 : i);
        expect_sorted_like_std(extremes, 64, digit_bits, scratch, "64-bit extremes");
    }
}

TEST(RadixSort, OddAndEvenPassCounts) {
    // 3, 4, 5 and 6 real passes: the result must land in the caller's
    // vectors whichever buffer the last pass wrote.
    std::mt19937_64 rng(3);
    RadixScratch scratch;
    for (int key_bits : {24, 32, 40, 48})
        expect_sorted_like_std(random_keys(10000, key_bits, rng), key_bits, 8, scratch, "pass parity");
}

// Once the scratch has grown, sorting as many keys again allocates nothing.
TEST(RadixSort, WarmScratchDoesNotAllocate) {
    std::mt19937_64 rng(4);
    RadixScratch scratch;
    std::vector<uint64_t> keys = random_keys(4096, 30, rng);
    std::vector<uint32_t> values(keys.size(), 0);
    for (int digit_bits : kDigitSizes) {
        const RadixSortOptions options{30, digit_bits};
        octoprox::radix_sort(keys, values, scratch, options);  // warms the scratch
        for (int round = 0; round < 5; ++round) {
            for (uint64_t &k : keys) k = rng() & ((uint64_t{1} << 30) - 1);
            const uint64_t before = unit::allocation_count();
            octoprox::radix_sort(keys, values, scratch, options);
            EXPECT_EQ(unit::allocation_count(), before) << "digit " << digit_bits;
            EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
        }
    }
}
