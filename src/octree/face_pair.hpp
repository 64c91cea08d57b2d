// The face parameters of two rays walked side by side, one in each lane
// of a pair of doubles: each advance picks, for both rays at once and
// without a branch, the axis whose next face comes first, ties to the
// higher axis (OctoMap's comparisons), and moves that face on.  Which axis
// comes next is as good as random, so a branch would be mispredicted
// about every other step; two rays share the instructions of one.
#pragma once

#include "octree/ray_setup.hpp"

#include <algorithm>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace octoprox {

// What advance() returns, per lane: which axis stepped, and whether the
// ray is past its end point after the step.
struct FaceStep {
    unsigned bits;
    int axis(int lane) const { return 2 - 2 * ((bits >> lane) & 1) - ((bits >> (2 + lane)) & 1); }
    bool past_end(int lane) const { return ((bits >> (4 + lane)) & 1) != 0; }
};

#if defined(__SSE2__)
class FacePair {
public:
    FacePair() {
        for (int i = 0; i < 3; ++i) t_[i] = d_[i] = _mm_setzero_pd();
        length_ = _mm_set1_pd(std::numeric_limits<double>::infinity());
    }
    void load(int lane, const RaySetup &ray) {
        for (int i = 0; i < 3; ++i) {
            set(t_[i], lane, ray.next_face[i]);
            set(d_[i], lane, ray.face_spacing[i]);
        }
        set(length_, lane, ray.length);
    }
    // An idle lane: its faces stay at 0 and it is never past its end.
    void idle(int lane) {
        for (int i = 0; i < 3; ++i) set(t_[i], lane, 0.0), set(d_[i], lane, 0.0);
        set(length_, lane, std::numeric_limits<double>::infinity());
    }
    FaceStep advance() {
        const __m128d c01 = _mm_cmplt_pd(t_[0], t_[1]), c02 = _mm_cmplt_pd(t_[0], t_[2]);
        const __m128d c12 = _mm_cmplt_pd(t_[1], t_[2]);
        const __m128d is0 = _mm_and_pd(c01, c02), is1 = _mm_andnot_pd(c01, c12);
        const __m128d is2 = _mm_andnot_pd(_mm_or_pd(is0, is1), _mm_castsi128_pd(_mm_set1_epi32(-1)));
        t_[0] = select(is0, _mm_add_pd(t_[0], d_[0]), t_[0]);
        t_[1] = select(is1, _mm_add_pd(t_[1], d_[1]), t_[1]);
        t_[2] = select(is2, _mm_add_pd(t_[2], d_[2]), t_[2]);
        const __m128d nearest = _mm_min_pd(_mm_min_pd(t_[0], t_[1]), t_[2]);
        const __m128d past = _mm_cmpgt_pd(nearest, length_);
        return FaceStep{static_cast<unsigned>(_mm_movemask_pd(is0) | (_mm_movemask_pd(is1) << 2) |
                                              (_mm_movemask_pd(past) << 4))};
    }

private:
    static __m128d select(__m128d mask, __m128d yes, __m128d no) {
        return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
    }
    static void set(__m128d &pair, int lane, double value) {
        pair = lane == 0 ? _mm_move_sd(pair, _mm_set_sd(value)) : _mm_unpacklo_pd(pair, _mm_set_sd(value));
    }
    __m128d t_[3], d_[3], length_;
};
#else
class FacePair {
public:
    FacePair() {
        for (int lane = 0; lane < 2; ++lane) idle(lane);
    }
    void load(int lane, const RaySetup &ray) {
        for (int i = 0; i < 3; ++i) t_[i][lane] = ray.next_face[i], d_[i][lane] = ray.face_spacing[i];
        length_[lane] = ray.length;
    }
    void idle(int lane) {
        for (int i = 0; i < 3; ++i) t_[i][lane] = d_[i][lane] = 0.0;
        length_[lane] = std::numeric_limits<double>::infinity();
    }
    FaceStep advance() {
        unsigned bits = 0;
        for (int lane = 0; lane < 2; ++lane) {
            double &t0 = t_[0][lane], &t1 = t_[1][lane], &t2 = t_[2][lane];
            const bool c01 = t0 < t1, c02 = t0 < t2, c12 = t1 < t2;
            const bool is0 = c01 && c02, is1 = !c01 && c12;
            if (is0) t0 += d_[0][lane];
            else if (is1) t1 += d_[1][lane];
            else t2 += d_[2][lane];
            const bool past = std::min(std::min(t0, t1), t2) > length_[lane];
            bits |= (unsigned{is0} << lane) | (unsigned{is1} << (2 + lane)) | (unsigned{past} << (4 + lane));
        }
        return FaceStep{bits};
    }

private:
    double t_[3][2], d_[3][2], length_[2];
};
#endif

}  // namespace octoprox
