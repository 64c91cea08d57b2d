// The convex hull of a point set as a closed triangle mesh, by adding the
// points one at a time to a starting tetrahedron.  Points within a tiny
// tolerance of a face (1e-12 of the set's size) count as on it, so near
// coplanar points do not split faces into slivers; every point lies at
// most a few times that tolerance outside the result, which is checked
// before it is returned.
#pragma once

#include "geometry/pose.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace octoprox {

struct HullMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<uint32_t, 3>> triangles;  // outward: (v1 - v0) x (v2 - v0) points out
};

// False, with `hull` empty, when the points span no volume (fewer than
// four, or all on a plane) or when the result fails its own check.
bool convex_hull(const std::vector<Vec3> &points, HullMesh &hull);

}  // namespace octoprox
