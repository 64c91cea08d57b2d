// Built with -ffp-contract=off (src/CMakeLists.txt): a fused multiply-add
// would round differently from OctoMap's separate operations.
#include "octree/ray_setup.hpp"

#include "octree/bounded_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {

// The direction and length in float, the face positions in double from
// the origin cell's centre and a float half-cell, as OctoMap has them.
RaySetup ray_setup(const BoundedOcTree &tree, const octomap::OcTreeKey &origin_key,
                   const octomap::point3d &origin, const octomap::point3d &end) {
    RaySetup s;
    octomap::point3d direction = end - origin;
    s.length = static_cast<float>(direction.norm());
    direction /= s.length;
    const double resolution = tree.getResolution();
    for (int i = 0; i < 3; ++i) {
        const float d = direction(i);
        s.step[i] = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
        if (s.step[i] == 0) {
            s.next_face[i] = std::numeric_limits<double>::max();
            s.face_spacing[i] = std::numeric_limits<double>::max();
            continue;
        }
        double face = tree.keyToCoord(origin_key[i]);
        face += static_cast<float>(s.step[i] * resolution * 0.5);
        s.next_face[i] = (face - origin(i)) / d;
        s.face_spacing[i] = resolution / std::fabs(d);
    }
    return s;
}

BitMoves bit_moves(const RaySetup &ray, const FrameMarks &marks) {
    BitMoves m;
    for (int i = 0; i < 3; ++i) {
        m.in_brick[i] = ray.step[i] * marks.unit_step(i);
        m.brick_change[i] = ray.step[i] * (marks.brick_step(i) - 8 * marks.unit_step(i));
        m.edge_mask[i] = uint64_t{brick::kMask} << (brick::kShift * i);
        m.edge_value[i] = ray.step[i] > 0 ? m.edge_mask[i] : 0;
    }
    return m;
}

}  // namespace octoprox
