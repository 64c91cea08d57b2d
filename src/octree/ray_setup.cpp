// Built with -ffp-contract=off and -fno-tree-vectorize (src/CMakeLists.txt):
// a fused multiply-add would round differently from OctoMap's separate
// operations, and GCC 12's vectorizer drops float roundings.
#include "octree/ray_setup.hpp"

#include "octree/bounded_tree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {

RayOrigin ray_origin(const BoundedOcTree &tree, const octomap::OcTreeKey &origin_key,
                     const octomap::point3d &origin) {
    RayOrigin o;
    o.point = origin;
    o.resolution = tree.getResolution();
    // OctoMap moves from the cell's centre to a face by a half cell
    // rounded to float.
    const float half_cell[2] = {static_cast<float>(-1 * o.resolution * 0.5),
                                static_cast<float>(1 * o.resolution * 0.5)};
    for (int i = 0; i < 3; ++i)
        for (int side = 0; side < 2; ++side) {
            double face = tree.keyToCoord(origin_key[i]);
            face += half_cell[side];
            o.to_face[i][side] = face - origin(i);
        }
    return o;
}

// The direction and length in float, the face parameters in double, as
// OctoMap has them.
RaySetup ray_setup(const RayOrigin &origin, const octomap::point3d &end) {
    RaySetup s;
    octomap::point3d direction = end - origin.point;
    s.length = static_cast<float>(direction.norm());
    direction /= s.length;
    for (int i = 0; i < 3; ++i) {
        const float d = direction(i);
        s.step[i] = d > 0.0 ? 1 : (d < 0.0 ? -1 : 0);
        if (s.step[i] == 0) {
            s.next_face[i] = std::numeric_limits<double>::max();
            s.face_spacing[i] = std::numeric_limits<double>::max();
            continue;
        }
        s.next_face[i] = origin.to_face[i][s.step[i] > 0] / d;
        s.face_spacing[i] = origin.resolution / std::fabs(d);
    }
    return s;
}

BitMoves bit_moves(const int step[3], const FrameMarks &marks) {
    BitMoves m;
    for (int i = 0; i < 3; ++i) {
        m.in_brick[i] = step[i] * marks.unit_step(i);
        m.brick_change[i] = step[i] * (marks.brick_step(i) - 8 * marks.unit_step(i));
        m.edge_mask[i] = uint64_t{brick::kMask} << (brick::kShift * i);
        m.edge_value[i] = step[i] > 0 ? m.edge_mask[i] : 0;
    }
    return m;
}

}  // namespace octoprox
