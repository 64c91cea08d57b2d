#include "octree/ray_walk.hpp"

#include "base/avx2.hpp"
#include "octree/bounded_tree.hpp"
#include "octree/face_pair.hpp"
#include "octree/ray_queue.hpp"

namespace octoprox {
namespace {

// Two rays at a time, each lane refilled as soon as its ray is done.  The
// lanes are spelled out, and the face pair never leaves this function, so
// that both stay in registers.
void walk_two(RayQueue &queue, FrameMarks &marks) {
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

}  // namespace

RayWalker::RayWalker(const BoundedOcTree &tree, const octomap::point3d &origin,
                     const octomap::OcTreeKey &origin_key)
    : origin_(ray_origin(tree, origin_key, origin)), origin_key_(origin_key) {}

void RayWalker::walk(const std::vector<octomap::point3d> &ends, const std::vector<octomap::OcTreeKey> &end_keys,
                     size_t begin, size_t end, FrameMarks &marks, std::vector<uint32_t> &strays,
                     RayLanes lanes) const {
    RayQueue queue(origin_, origin_key_, ends, end_keys, begin, end, marks, strays);
    const bool four = lanes != RayLanes::kTwo && cpu_has_avx2();
    if (four) walk_four(queue, marks);
    else walk_two(queue, marks);
}

}  // namespace octoprox
