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
    const double inverse_resolution = 1.0 / resolution;
    for (int i = 0; i < 3; ++i) {
        const float d = direction(i);
        s.faces_per_metre[i] = 0.0;
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
        s.faces_per_metre[i] = std::fabs(d) * inverse_resolution;
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

// An axis steps only while its face parameter is at most the length (one
// first step aside), and the accumulated parameters are within 2^-19 of a
// cell of their exact values, so the reach below, with a relative and two
// cells of slack, is never exceeded.  Faces are counted by multiplying
// with |direction| / resolution (the inverse of the face spacing, to a
// relative 1e-15), sparing a division per axis.
bool stays_in_box(const RaySetup &ray, const uint32_t origin[3], const FrameMarks &marks) {
    for (int i = 0; i < 3; ++i) {
        if (ray.step[i] == 0) continue;
        const double faces = std::max(0.0, (ray.length - ray.next_face[i]) * ray.faces_per_metre[i]);
        const double reach = std::floor(faces * (1.0 + 1e-6)) + 3.0;
        const double lo = marks.lowest_key()[i];
        const double hi = lo + 8.0 * marks.bricks_per_axis()[i] - 1.0;
        const double farthest = origin[i] + ray.step[i] * reach;
        if (!(farthest >= lo && farthest <= hi)) return false;
    }
    return true;
}

}  // namespace octoprox
