// ray_setup for four rays in the lanes of AVX2 vectors: the same float
// and double operations in the same order (no fused multiply-add), a
// division per axis shared by four rays.
#include "octree/ray_setup.hpp"

#include "base/avx2.hpp"

#include <limits>

#if defined(OPX_AVX2_LANES)

namespace octoprox {
namespace {

// Four floats' step direction: 1, -1 or 0.
OPX_AVX2 __m128i step_of(__m128 d) {
    const __m128 zero = _mm_setzero_ps();
    const __m128i positive = _mm_castps_si128(_mm_cmpgt_ps(d, zero));
    const __m128i negative = _mm_castps_si128(_mm_cmplt_ps(d, zero));
    // true is -1: a positive lane gives 0 - (-1) = 1, a negative one -1.
    return _mm_sub_epi32(negative, positive);
}

}  // namespace

OPX_AVX2 void ray_setup_four(const RayOrigin &origin, const octomap::point3d *const ends[4], RaySetupFour &out) {
    __m128 d[3];
    for (int i = 0; i < 3; ++i)
        d[i] = _mm_sub_ps(_mm_setr_ps((*ends[0])(i), (*ends[1])(i), (*ends[2])(i), (*ends[3])(i)),
                          _mm_set1_ps(origin.point(i)));
    // Vector3::norm: the squares summed in float, the root in double.
    const __m128 squares =
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(d[0], d[0]), _mm_mul_ps(d[1], d[1])), _mm_mul_ps(d[2], d[2]));
    const __m128 length = _mm256_cvtpd_ps(_mm256_sqrt_pd(_mm256_cvtps_pd(squares)));
    _mm256_store_pd(out.length, _mm256_cvtps_pd(length));
    const __m256d resolution = _mm256_set1_pd(origin.resolution);
    const __m256d none = _mm256_set1_pd(std::numeric_limits<double>::max());
    for (int i = 0; i < 3; ++i) {
        const __m128 unit = _mm_div_ps(d[i], length);
        const __m128i step = step_of(unit);
        const __m256d wide = _mm256_cvtps_pd(unit);
        const __m256d positive = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm_cmpgt_epi32(step, _mm_setzero_si128())));
        const __m256d to_face =
            _mm256_blendv_pd(_mm256_set1_pd(origin.to_face[i][0]), _mm256_set1_pd(origin.to_face[i][1]), positive);
        const __m256d moves = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(_mm_xor_si128(
            _mm_cmpeq_epi32(step, _mm_setzero_si128()), _mm_set1_epi32(-1))));
        const __m256d magnitude = _mm256_andnot_pd(_mm256_set1_pd(-0.0), wide);
        _mm256_store_pd(out.next_face[i], _mm256_blendv_pd(none, _mm256_div_pd(to_face, wide), moves));
        _mm256_store_pd(out.face_spacing[i], _mm256_blendv_pd(none, _mm256_div_pd(resolution, magnitude), moves));
        _mm256_store_si256(reinterpret_cast<__m256i *>(out.step[i]), _mm256_cvtepi32_epi64(step));
    }
}

}  // namespace octoprox

#else

namespace octoprox {
void ray_setup_four(const RayOrigin &, const octomap::point3d *const[4], RaySetupFour &) {}
}  // namespace octoprox

#endif
