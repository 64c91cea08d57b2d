#include "broadphase/radix_sort.hpp"

#include <algorithm>
#include <cstddef>

namespace octoprox {
namespace {

int pass_count(int key_bits, int digit_bits) { return (key_bits + digit_bits - 1) / digit_bits; }

// All histograms in one read of the keys (counts[pass * radix + digit]).
void count_digits(const std::vector<uint64_t> &keys, int passes, int digit_bits, uint32_t *counts) {
    const size_t radix = size_t{1} << digit_bits;
    const uint64_t mask = radix - 1;
    std::fill(counts, counts + passes * radix, 0u);
    for (const uint64_t key : keys) {
        uint64_t rest = key;
        for (int pass = 0; pass < passes; ++pass, rest >>= digit_bits) ++counts[pass * radix + (rest & mask)];
    }
}

// True when every key has the same digit in this pass (nothing to reorder).
bool is_trivial(const uint32_t *counts, size_t radix, size_t n) {
    for (size_t digit = 0; digit < radix; ++digit)
        if (counts[digit] != 0) return counts[digit] == n;
    return true;
}

// Counts become start offsets (exclusive prefix sums).
void to_offsets(uint32_t *counts, size_t radix) {
    uint32_t sum = 0;
    for (size_t digit = 0; digit < radix; ++digit) {
        const uint32_t count = counts[digit];
        counts[digit] = sum;
        sum += count;
    }
}

void scatter(const uint64_t *keys_in, const uint32_t *values_in, uint64_t *keys_out,
             uint32_t *values_out, size_t n, int shift, uint64_t mask, uint32_t *offsets) {
    for (size_t i = 0; i < n; ++i) {
        const uint32_t at = offsets[(keys_in[i] >> shift) & mask]++;
        keys_out[at] = keys_in[i];
        values_out[at] = values_in[i];
    }
}

}  // namespace

void radix_sort(std::vector<uint64_t> &keys, std::vector<uint32_t> &values, RadixScratch &scratch,
                const RadixSortOptions &options) {
    const size_t n = keys.size();
    if (n < 2) return;
    const int digit_bits = std::clamp(options.digit_bits, 1, 16);
    const int key_bits = std::clamp(options.key_bits, 1, 64);
    const int passes = pass_count(key_bits, digit_bits);
    const size_t radix = size_t{1} << digit_bits;
    const uint64_t mask = radix - 1;

    // resize() never shrinks capacity: warm buffers do not allocate.
    scratch.counts.resize(passes * radix);
    count_digits(keys, passes, digit_bits, scratch.counts.data());
    scratch.keys.resize(n);
    scratch.values.resize(n);

    // Ping-pong between the caller's vectors and the scratch ones.
    uint64_t *key_src = keys.data(), *key_dst = scratch.keys.data();
    uint32_t *value_src = values.data(), *value_dst = scratch.values.data();
    for (int pass = 0; pass < passes; ++pass) {
        uint32_t *counts = scratch.counts.data() + pass * radix;
        if (is_trivial(counts, radix, n)) continue;
        to_offsets(counts, radix);
        scatter(key_src, value_src, key_dst, value_dst, n, pass * digit_bits, mask, counts);
        std::swap(key_src, key_dst);
        std::swap(value_src, value_dst);
    }
    // An odd number of real passes left the result in the scratch buffers;
    // swapping the vectors hands them over without a copy.
    if (key_src != keys.data()) {
        keys.swap(scratch.keys);
        values.swap(scratch.values);
    }
}

}  // namespace octoprox
