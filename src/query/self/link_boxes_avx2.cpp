// overlap_bits four boxes at a time in AVX2 lanes (target attributes, not
// a compiler flag for the file: the function runs only where the
// processor has AVX2; link_boxes.cpp asks).
#include "query/self/link_boxes.hpp"

#include "base/avx2.hpp"

namespace octoprox {

#if defined(OPX_AVX2_LANES)

// Lanes past `count` may hold later entries or padding: their bits are
// cleared at the end.
OPX_AVX2 uint64_t overlap_bits_avx2(const BoxRows &rows, size_t row, size_t first, size_t count, uint64_t wanted) {
    __m256d row_lo[3], row_hi[3];
    for (int axis = 0; axis < 3; ++axis)
        row_lo[axis] = _mm256_set1_pd(rows.lo[axis][row]), row_hi[axis] = _mm256_set1_pd(rows.hi[axis][row]);
    uint64_t bits = 0;
    for (size_t k = 0; k < count; k += 4) {
        if (((wanted >> k) & 0xF) == 0) continue;
        const size_t j = first + k;
        __m256d overlap = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
        for (int axis = 0; axis < 3; ++axis) {
            const __m256d lo = _mm256_loadu_pd(&rows.lo[axis][j]), hi = _mm256_loadu_pd(&rows.hi[axis][j]);
            overlap = _mm256_and_pd(overlap, _mm256_cmp_pd(lo, row_hi[axis], _CMP_LE_OQ));
            overlap = _mm256_and_pd(overlap, _mm256_cmp_pd(row_lo[axis], hi, _CMP_LE_OQ));
        }
        bits |= static_cast<uint64_t>(_mm256_movemask_pd(overlap)) << k;
    }
    bits &= wanted;
    return count < 64 ? bits & ((uint64_t{1} << count) - 1) : bits;
}

#else

uint64_t overlap_bits_avx2(const BoxRows &, size_t, size_t, size_t, uint64_t) { return 0; }

#endif

}  // namespace octoprox
