#include "octree/ray_walk.hpp"

#include "octree/bounded_tree.hpp"
#include "octree/face_pair.hpp"
#include "octree/ray_setup.hpp"

namespace octoprox {
namespace {

// One ray's place in the marks.  Inside the box a key and its bit
// determine each other, so the bit alone is stepped and compared.
struct LaneRay {
    uint64_t bit = 0, last_bit = 0;
    BitMoves moves{};

    // One step along `axis`; false once the ray is done.
    bool step(int axis, bool past_end) {
        const uint64_t leaves_brick = uint64_t{0} - ((bit & moves.edge_mask[axis]) == moves.edge_value[axis]);
        bit += moves.in_brick[axis] + static_cast<int64_t>(leaves_brick & moves.brick_change[axis]);
        // The end's cell is not marked; past the end point without meeting
        // it (rounding) the ray is done too.
        return bit != last_bit && !past_end;
    }
};

// The rays of one range, handed to the lanes one after another.
class RayQueue {
public:
    RayQueue(const BoundedOcTree &tree, const octomap::point3d &origin, const octomap::OcTreeKey &origin_key,
             const std::vector<octomap::point3d> &ends, const std::vector<octomap::OcTreeKey> &end_keys,
             size_t begin, size_t end, FrameMarks &marks, std::vector<uint32_t> &strays)
        : tree_(tree), origin_(origin), origin_key_(origin_key), ends_(ends), end_keys_(end_keys), next_(begin),
          end_(end), marks_(marks), strays_(strays) {
        for (int i = 0; i < 3; ++i) origin_cell_[i] = origin_key[i];
        origin_bit_ = marks.bit_of(origin_cell_);
    }

    // The next ray with cells to walk, false when none is left.
    bool next(LaneRay &ray, RaySetup &setup) {
        while (next_ < end_) {
            const size_t index = next_++;
            const octomap::OcTreeKey &key = end_keys_[index];
            if (key == origin_key_) continue;  // inside the origin's cell: no cell to free
            setup = ray_setup(tree_, origin_key_, origin_, ends_[index]);
            if (!stays_in_box(setup, origin_cell_, marks_)) {
                strays_.push_back(static_cast<uint32_t>(index));
                continue;
            }
            const uint32_t end_cell[3] = {key[0], key[1], key[2]};
            ray.moves = bit_moves(setup, marks_);
            ray.bit = origin_bit_;
            ray.last_bit = marks_.bit_of(end_cell);
            marks_.mark_crossed(origin_bit_);
            return true;
        }
        return false;
    }

private:
    const BoundedOcTree &tree_;
    const octomap::point3d origin_;
    const octomap::OcTreeKey origin_key_;
    uint32_t origin_cell_[3];
    uint64_t origin_bit_ = 0;
    const std::vector<octomap::point3d> &ends_;
    const std::vector<octomap::OcTreeKey> &end_keys_;
    size_t next_;
    const size_t end_;
    FrameMarks &marks_;
    std::vector<uint32_t> &strays_;
};

}  // namespace

RayWalker::RayWalker(const BoundedOcTree &tree, const octomap::point3d &origin,
                     const octomap::OcTreeKey &origin_key)
    : tree_(tree), origin_(origin), origin_key_(origin_key) {}

// Two rays at a time, each lane refilled as soon as its ray is done.  The
// lanes are spelled out, and the face pair never leaves this function, so
// that both stay in registers.
void RayWalker::walk(const std::vector<octomap::point3d> &ends, const std::vector<octomap::OcTreeKey> &end_keys,
                     size_t begin, size_t end, FrameMarks &marks, std::vector<uint32_t> &strays) const {
    RayQueue queue(tree_, origin_, origin_key_, ends, end_keys, begin, end, marks, strays);
    FacePair faces;
    LaneRay ray0, ray1;
    RaySetup setup;
    bool live0 = queue.next(ray0, setup);
    if (live0) faces.load(0, setup);
    bool live1 = queue.next(ray1, setup);
    if (live1) faces.load(1, setup);
    while (live0 | live1) {
        const FaceStep step = faces.advance();
        if (live0) {
            if (ray0.step(step.axis(0), step.past_end(0))) {
                marks.mark_crossed(ray0.bit);
            } else {
                live0 = queue.next(ray0, setup);
                if (live0) faces.load(0, setup);
                else faces.idle(0);
            }
        }
        if (live1) {
            if (ray1.step(step.axis(1), step.past_end(1))) {
                marks.mark_crossed(ray1.bit);
            } else {
                live1 = queue.next(ray1, setup);
                if (live1) faces.load(1, setup);
                else faces.idle(1);
            }
        }
    }
}

}  // namespace octoprox
