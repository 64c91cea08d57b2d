// LSD radix sort of 64-bit keys carrying 32-bit payloads (the box indices
// of a Morton build): linear time, stable, and allocation-free once the
// caller's scratch buffers have grown to the largest input.
#pragma once

#include <cstdint>
#include <vector>

namespace octoprox {

// Buffers reused across sorts; keep one per builder.
struct RadixScratch {
    std::vector<uint64_t> keys;
    std::vector<uint32_t> values;
    std::vector<uint32_t> counts;  // one histogram per digit position
};

struct RadixSortOptions {
    int key_bits = 64;    // only the low key_bits bits are sorted on (1..64)
    int digit_bits = 8;   // 8 (256 buckets) or 11 (2048 buckets); clamped to [1, 16]
};

// Sorts keys ascending, applying the same permutation to values (which must
// be as long as keys).  Stable: equal keys keep their input order, so with
// values = 0..n-1 the result equals std::sort on (key, value) pairs.  Bits
// above key_bits must be zero (they are ignored).  Passes whose digit is the
// same for every key are skipped, so constant or narrow keys cost one
// counting pass.
void radix_sort(std::vector<uint64_t> &keys, std::vector<uint32_t> &values, RadixScratch &scratch,
                const RadixSortOptions &options = RadixSortOptions());

}  // namespace octoprox
