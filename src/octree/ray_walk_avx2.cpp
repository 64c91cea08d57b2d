// Four rays stepped at once in the lanes of AVX2 vectors: the face choice,
// the face parameters and the ray's bit all move without a branch, and a
// lane is refilled from the queue when its ray is done.  Each lane does,
// operation for operation, what LaneRay and FacePair do for one ray
// (IEEE doubles, no fused multiply-add), so the cells are the same.
//
// Only this file's functions use AVX2 (target attributes, not a compiler
// flag for the file), and they run only where the processor has it.
#include "octree/ray_queue.hpp"
#include "octree/ray_walk.hpp"

#include "base/avx2.hpp"

#include <limits>

namespace octoprox {

#if defined(OPX_AVX2_LANES)

namespace {

constexpr int kLanes = 4;

// The queue's rays, set up four at a time (ray_setup_four) and handed out
// one by one.
class RayBatch {
public:
    explicit RayBatch(RayQueue &queue) : queue_(queue) {}

    // The set-up is read in place: copying it whole right after
    // ray_setup_four wrote it field by field would stall on the stores.
    const RaySetup *next(LaneRay &ray) {
        if (taken_ == count_ && !fill()) return nullptr;
        const int i = taken_++;
        queue_.start(indices_[i], setups_[i], ray);
        return &setups_[i];
    }
    uint64_t origin_bit() const { return queue_.origin_bit(); }

private:
    bool fill() {
        count_ = taken_ = 0;
        while (count_ < kLanes && queue_.next_index(indices_[count_])) ++count_;
        if (count_ == 0) return false;
        const octomap::point3d *ends[kLanes];
        for (int i = 0; i < kLanes; ++i) ends[i] = &queue_.end_point(indices_[i < count_ ? i : count_ - 1]);
        ray_setup_four(queue_.origin(), ends, setups_);
        return true;
    }

    RayQueue &queue_;
    size_t indices_[kLanes];
    RaySetup setups_[kLanes];
    int count_ = 0, taken_ = 0;
};

// Every lane's state, lane after lane, for loading into vectors and for
// refilling one lane.  An idle lane never ends, never moves and marks
// the origin's cell, which its walk has marked already.
struct alignas(32) Lanes {
    double face[3][kLanes], spacing[3][kLanes], length[kLanes];
    int64_t bit[kLanes], last_bit[kLanes];
    int64_t in_brick[3][kLanes], brick_change[3][kLanes], edge_value[3][kLanes];
    bool live[kLanes];

    void load(int lane, const LaneRay &ray, const RaySetup &setup) {
        for (int axis = 0; axis < 3; ++axis) {
            face[axis][lane] = setup.next_face[axis];
            spacing[axis][lane] = setup.face_spacing[axis];
            in_brick[axis][lane] = ray.moves.in_brick[axis];
            brick_change[axis][lane] = ray.moves.brick_change[axis];
            edge_value[axis][lane] = static_cast<int64_t>(ray.moves.edge_value[axis]);
        }
        length[lane] = setup.length;
        bit[lane] = static_cast<int64_t>(ray.bit);
        last_bit[lane] = static_cast<int64_t>(ray.last_bit);
        live[lane] = true;
    }

    void idle(int lane, uint64_t origin_bit) {
        for (int axis = 0; axis < 3; ++axis) {
            face[axis][lane] = spacing[axis][lane] = 0.0;
            in_brick[axis][lane] = brick_change[axis][lane] = edge_value[axis][lane] = 0;
        }
        length[lane] = std::numeric_limits<double>::infinity();
        bit[lane] = static_cast<int64_t>(origin_bit);
        last_bit[lane] = -1;  // no bit
        live[lane] = false;
    }

    // Fills the lane with the queue's next ray; false when none is left.
    bool refill(int lane, RayBatch &rays) {
        LaneRay ray;
        if (const RaySetup *setup = rays.next(ray)) {
            load(lane, ray, *setup);
            return true;
        }
        idle(lane, rays.origin_bit());
        return false;
    }
};

OPX_AVX2 inline __m256d pick(__m256d is0, __m256d is1, const double (&value)[3][kLanes]) {
    const __m256d v12 = _mm256_blendv_pd(_mm256_load_pd(value[2]), _mm256_load_pd(value[1]), is1);
    return _mm256_blendv_pd(v12, _mm256_load_pd(value[0]), is0);
}

OPX_AVX2 inline __m256i pick(__m256d is0, __m256d is1, const int64_t (&value)[3][kLanes]) {
    const __m256d v0 = _mm256_castsi256_pd(_mm256_load_si256(reinterpret_cast<const __m256i *>(value[0])));
    const __m256d v1 = _mm256_castsi256_pd(_mm256_load_si256(reinterpret_cast<const __m256i *>(value[1])));
    const __m256d v2 = _mm256_castsi256_pd(_mm256_load_si256(reinterpret_cast<const __m256i *>(value[2])));
    return _mm256_castpd_si256(_mm256_blendv_pd(_mm256_blendv_pd(v2, v1, is1), v0, is0));
}

// The walk proper, between two refills: steps every lane until one is
// done.  Returns the done lanes' mask; the vectors of `lanes` that move
// (faces, bits) are written back.
OPX_AVX2 unsigned step_until_done(Lanes &lanes, FrameMarks &marks) {
    const __m256i edge_mask[3] = {_mm256_set1_epi64x(brick::kMask), _mm256_set1_epi64x(brick::kMask << brick::kShift),
                                  _mm256_set1_epi64x(brick::kMask << (2 * brick::kShift))};
    __m256d t0 = _mm256_load_pd(lanes.face[0]), t1 = _mm256_load_pd(lanes.face[1]);
    __m256d t2 = _mm256_load_pd(lanes.face[2]);
    const __m256d d0 = _mm256_load_pd(lanes.spacing[0]), d1 = _mm256_load_pd(lanes.spacing[1]);
    const __m256d d2 = _mm256_load_pd(lanes.spacing[2]), length = _mm256_load_pd(lanes.length);
    __m256i bit = _mm256_load_si256(reinterpret_cast<const __m256i *>(lanes.bit));
    const __m256i last = _mm256_load_si256(reinterpret_cast<const __m256i *>(lanes.last_bit));
    alignas(32) int64_t bits[kLanes];
    for (;;) {
        // The axis whose face comes first, ties to the higher axis.
        const __m256d c01 = _mm256_cmp_pd(t0, t1, _CMP_LT_OQ), c02 = _mm256_cmp_pd(t0, t2, _CMP_LT_OQ);
        const __m256d c12 = _mm256_cmp_pd(t1, t2, _CMP_LT_OQ);
        const __m256d is0 = _mm256_and_pd(c01, c02), is1 = _mm256_andnot_pd(c01, c12);
        t0 = _mm256_blendv_pd(t0, _mm256_add_pd(t0, d0), is0);
        t1 = _mm256_blendv_pd(t1, _mm256_add_pd(t1, d1), is1);
        t2 = _mm256_blendv_pd(_mm256_add_pd(t2, d2), t2, _mm256_or_pd(is0, is1));
        const __m256d past = _mm256_cmp_pd(_mm256_min_pd(_mm256_min_pd(t0, t1), t2), length, _CMP_GT_OQ);
        // The bit's move along that axis, into the next brick when the
        // in-brick coordinate is at the brick's edge.
        const __m256i mask = _mm256_castpd_si256(_mm256_blendv_pd(
            _mm256_blendv_pd(_mm256_castsi256_pd(edge_mask[2]), _mm256_castsi256_pd(edge_mask[1]), is1),
            _mm256_castsi256_pd(edge_mask[0]), is0));
        const __m256i leaves = _mm256_cmpeq_epi64(_mm256_and_si256(bit, mask), pick(is0, is1, lanes.edge_value));
        const __m256i move = _mm256_add_epi64(pick(is0, is1, lanes.in_brick),
                                              _mm256_and_si256(leaves, pick(is0, is1, lanes.brick_change)));
        bit = _mm256_add_epi64(bit, move);
        const __m256d done = _mm256_or_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(bit, last)), past);
        const unsigned done_lanes = static_cast<unsigned>(_mm256_movemask_pd(done));
        _mm256_store_si256(reinterpret_cast<__m256i *>(bits), bit);
        if (done_lanes == 0) {
            for (int lane = 0; lane < kLanes; ++lane) marks.mark_crossed(static_cast<uint64_t>(bits[lane]));
            continue;
        }
        for (int lane = 0; lane < kLanes; ++lane)
            if ((done_lanes >> lane & 1) == 0) marks.mark_crossed(static_cast<uint64_t>(bits[lane]));
        _mm256_store_pd(lanes.face[0], t0);
        _mm256_store_pd(lanes.face[1], t1);
        _mm256_store_pd(lanes.face[2], t2);
        _mm256_store_si256(reinterpret_cast<__m256i *>(lanes.bit), bit);
        return done_lanes;
    }
}

}  // namespace

OPX_AVX2 void walk_four(RayQueue &queue, FrameMarks &marks) {
    RayBatch rays(queue);
    Lanes lanes;
    int live = 0;
    for (int lane = 0; lane < kLanes; ++lane) live += lanes.refill(lane, rays);
    while (live > 0) {
        const unsigned done = step_until_done(lanes, marks);
        for (int lane = 0; lane < kLanes; ++lane)
            if ((done >> lane & 1) != 0 && lanes.live[lane]) live -= !lanes.refill(lane, rays);
    }
}

#else

void walk_four(RayQueue &, FrameMarks &) {}

#endif

}  // namespace octoprox
