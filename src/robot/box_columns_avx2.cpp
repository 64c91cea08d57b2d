// placed_union's loop four boxes at a time in AVX2 lanes (target
// attributes, not a compiler flag for the file: the function runs only
// where the processor has AVX2; box_columns.cpp asks).
#include "robot/box_columns.hpp"

#include "base/avx2.hpp"

namespace octoprox {

#if defined(OPX_AVX2_LANES)

namespace {

OPX_AVX2 double lowest(__m256d v) {
    const __m128d pair = _mm_min_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
    return _mm_cvtsd_f64(_mm_min_sd(pair, _mm_unpackhi_pd(pair, pair)));
}

OPX_AVX2 double highest(__m256d v) {
    const __m128d pair = _mm_max_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
    return _mm_cvtsd_f64(_mm_max_sd(pair, _mm_unpackhi_pd(pair, pair)));
}

}  // namespace

OPX_AVX2 void placed_union_avx2(const BoxColumns &boxes, const double r[3][3], const double s[3][3],
                                const double t[3], double lo[3], double hi[3]) {
    const size_t padded = boxes.center[0].size();
    for (int i = 0; i < 3; ++i) {
        const __m256d r0 = _mm256_set1_pd(r[i][0]), r1 = _mm256_set1_pd(r[i][1]), r2 = _mm256_set1_pd(r[i][2]);
        const __m256d s0 = _mm256_set1_pd(s[i][0]), s1 = _mm256_set1_pd(s[i][1]), s2 = _mm256_set1_pd(s[i][2]);
        const __m256d ti = _mm256_set1_pd(t[i]);
        __m256d low = _mm256_set1_pd(lo[i]), high = _mm256_set1_pd(hi[i]);
        for (size_t b = 0; b < padded; b += 4) {
            const __m256d middle = _mm256_add_pd(
                _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(r0, _mm256_loadu_pd(&boxes.center[0][b])),
                                            _mm256_mul_pd(r1, _mm256_loadu_pd(&boxes.center[1][b]))),
                              _mm256_mul_pd(r2, _mm256_loadu_pd(&boxes.center[2][b]))),
                ti);
            const __m256d half =
                _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(s0, _mm256_loadu_pd(&boxes.half[0][b])),
                                            _mm256_mul_pd(s1, _mm256_loadu_pd(&boxes.half[1][b]))),
                              _mm256_mul_pd(s2, _mm256_loadu_pd(&boxes.half[2][b])));
            low = _mm256_min_pd(low, _mm256_sub_pd(middle, half));
            high = _mm256_max_pd(high, _mm256_add_pd(middle, half));
        }
        lo[i] = lowest(low), hi[i] = highest(high);
    }
}

#else

void placed_union_avx2(const BoxColumns &, const double[3][3], const double[3][3], const double[3], double[3],
                       double[3]) {}

#endif

}  // namespace octoprox
