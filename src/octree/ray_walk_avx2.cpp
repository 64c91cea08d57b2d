// Four rays stepped at once in the lanes of AVX2 vectors: the face choice,
// the face parameters and the ray's bit all move without a branch.  Each
// lane does, operation for operation, what LaneRay and FacePair do for one
// ray (IEEE doubles, no fused multiply-add), so the cells are the same.
//
// The four rays of a group are set up together and walked together until
// the last of them is done; a lane whose ray is done marks nothing more.
// Neighbouring rays of a frame mostly end in one cell, so the rays of a
// group mostly take the same number of steps, and the lanes' state lives
// in registers from the set-up to the group's end: refilling a lane on its
// own would cost a mispredicted branch a ray and vector loads of what was
// just stored lane by lane.
//
// Only this file's functions use AVX2 (target attributes, not a compiler
// flag for the file), and they run only where the processor has it.
#include "octree/ray_queue.hpp"
#include "octree/ray_walk.hpp"

#include "base/avx2.hpp"

namespace octoprox {

#if defined(OPX_AVX2_LANES)

namespace {

constexpr int kLanes = 4;

// How a step along each axis moves each lane's bit (BitMoves, lane by
// lane), from the lanes' step directions.
struct LaneMoves {
    __m256i in_brick[3], brick_change[3], edge_value[3];
};

OPX_AVX2 LaneMoves lane_moves(const RaySetupFour &setup, const BitMoves &up) {
    LaneMoves m;
    for (int axis = 0; axis < 3; ++axis) {
        const __m256i step = _mm256_load_si256(reinterpret_cast<const __m256i *>(setup.step[axis]));
        const __m256i positive = _mm256_cmpgt_epi64(step, _mm256_setzero_si256());
        const __m256i in_brick = _mm256_set1_epi64x(up.in_brick[axis]);
        const __m256i change = _mm256_set1_epi64x(up.brick_change[axis]);
        // An axis without steps (0) is never chosen: it takes the moves down.
        m.in_brick[axis] = _mm256_blendv_epi8(_mm256_sub_epi64(_mm256_setzero_si256(), in_brick), in_brick, positive);
        m.brick_change[axis] = _mm256_blendv_epi8(_mm256_sub_epi64(_mm256_setzero_si256(), change), change, positive);
        m.edge_value[axis] = _mm256_and_si256(positive, _mm256_set1_epi64x(static_cast<int64_t>(up.edge_value[axis])));
    }
    return m;
}

OPX_AVX2 inline __m256i pick(__m256d is0, __m256d is1, const __m256i (&value)[3]) {
    const __m256d v0 = _mm256_castsi256_pd(value[0]), v1 = _mm256_castsi256_pd(value[1]);
    const __m256d v2 = _mm256_castsi256_pd(value[2]);
    return _mm256_castpd_si256(_mm256_blendv_pd(_mm256_blendv_pd(v2, v1, is1), v0, is0));
}

// Walks one group: every lane from the origin's cell until its ray is done.
// In rows (FrameMarks::in_rows) a step's move does not depend on where the
// bit is.
template <bool kInRows>
OPX_AVX2 void walk_group(const RaySetupFour &setup, const LaneMoves &moves, __m256i last, uint64_t origin_bit,
                         FrameMarks &marks) {
    const __m256i edge_mask[3] = {_mm256_set1_epi64x(brick::kMask), _mm256_set1_epi64x(brick::kMask << brick::kShift),
                                  _mm256_set1_epi64x(brick::kMask << (2 * brick::kShift))};
    __m256d t0 = _mm256_load_pd(setup.next_face[0]), t1 = _mm256_load_pd(setup.next_face[1]);
    __m256d t2 = _mm256_load_pd(setup.next_face[2]);
    const __m256d d0 = _mm256_load_pd(setup.face_spacing[0]), d1 = _mm256_load_pd(setup.face_spacing[1]);
    const __m256d d2 = _mm256_load_pd(setup.face_spacing[2]), length = _mm256_load_pd(setup.length);
    const __m256i origin = _mm256_set1_epi64x(static_cast<int64_t>(origin_bit));
    __m256i bit = origin;
    __m256d finished = _mm256_setzero_pd();
    alignas(32) int64_t bits[kLanes];
    for (;;) {
        // The axis whose face comes first, ties to the higher axis.
        const __m256d c01 = _mm256_cmp_pd(t0, t1, _CMP_LT_OQ), c02 = _mm256_cmp_pd(t0, t2, _CMP_LT_OQ);
        const __m256d c12 = _mm256_cmp_pd(t1, t2, _CMP_LT_OQ);
        const __m256d is0 = _mm256_and_pd(c01, c02), is1 = _mm256_andnot_pd(c01, c12);
        // Adding +0.0 leaves a face parameter (positive) as it is.
        t0 = _mm256_add_pd(t0, _mm256_and_pd(is0, d0));
        t1 = _mm256_add_pd(t1, _mm256_and_pd(is1, d1));
        t2 = _mm256_add_pd(t2, _mm256_andnot_pd(_mm256_or_pd(is0, is1), d2));
        const __m256d past = _mm256_cmp_pd(_mm256_min_pd(_mm256_min_pd(t0, t1), t2), length, _CMP_GT_OQ);
        // The bit's move along that axis, into the next brick when the
        // in-brick coordinate is at the brick's edge.
        if (kInRows) {
            bit = _mm256_add_epi64(bit, pick(is0, is1, moves.in_brick));
        } else {
            const __m256i leaves = _mm256_cmpeq_epi64(_mm256_and_si256(bit, pick(is0, is1, edge_mask)),
                                                      pick(is0, is1, moves.edge_value));
            const __m256i move = _mm256_add_epi64(pick(is0, is1, moves.in_brick),
                                                  _mm256_and_si256(leaves, pick(is0, is1, moves.brick_change)));
            bit = _mm256_add_epi64(bit, move);
        }
        // A lane is done at its end's cell (not marked) or past its end
        // point; from then on it marks the origin's cell, marked already.
        finished = _mm256_or_pd(finished, _mm256_or_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(bit, last)), past));
        _mm256_store_si256(reinterpret_cast<__m256i *>(bits),
                           _mm256_castpd_si256(_mm256_blendv_pd(_mm256_castsi256_pd(bit),
                                                                _mm256_castsi256_pd(origin), finished)));
        if (_mm256_movemask_pd(finished) == 0xF) return;
        for (int lane = 0; lane < kLanes; ++lane) marks.mark_crossed(static_cast<uint64_t>(bits[lane]));
    }
}

// Four rays with their set-up and the bits of their end cells.
struct alignas(32) RayGroup {
    RaySetupFour setup;
    int64_t last[kLanes];
    bool full = false;

    // Takes the queue's next rays; false when none is left.  A short group
    // repeats its last ray, which marks the same cells.
    OPX_AVX2 bool take(RayQueue &queue) {
        size_t index[kLanes];
        int count = 0;
        while (count < kLanes && queue.next_index(index[count])) ++count;
        if (count == 0) return false;
        full = count == kLanes;
        for (int lane = count; lane < kLanes; ++lane) index[lane] = index[count - 1];
        const octomap::point3d *ends[kLanes];
        for (int lane = 0; lane < kLanes; ++lane) ends[lane] = &queue.end_point(index[lane]);
        ray_setup_four(queue.origin(), ends, setup);
        _mm256_store_si256(reinterpret_cast<__m256i *>(last),
                           _mm256_setr_epi64x(static_cast<int64_t>(queue.end_bit(index[0])),
                                              static_cast<int64_t>(queue.end_bit(index[1])),
                                              static_cast<int64_t>(queue.end_bit(index[2])),
                                              static_cast<int64_t>(queue.end_bit(index[3]))));
        return true;
    }
};

template <bool kInRows>
OPX_AVX2 void walk_groups(RayQueue &queue, FrameMarks &marks) {
    const int up[3] = {1, 1, 1};
    const BitMoves up_moves = bit_moves(up, marks);
    RayGroup groups[2];
    int current = 0;
    if (!groups[current].take(queue)) return;
    marks.mark_crossed(queue.origin_bit());
    for (;;) {
        // The next group is set up before this one is walked: its
        // divisions and square roots then run beside the walk.
        RayGroup &group = groups[current], &next = groups[1 - current];
        const bool more = group.full && next.take(queue);
        walk_group<kInRows>(group.setup, lane_moves(group.setup, up_moves),
                   _mm256_load_si256(reinterpret_cast<const __m256i *>(group.last)), queue.origin_bit(), marks);
        if (!more) return;
        current = 1 - current;
    }
}

}  // namespace

void walk_four(RayQueue &queue, FrameMarks &marks) {
    if (marks.in_rows()) walk_groups<true>(queue, marks);
    else walk_groups<false>(queue, marks);
}

#else

void walk_four(RayQueue &, FrameMarks &) {}

#endif

}  // namespace octoprox
