// Whether a triangle mesh bounds a solid: every edge is shared by exactly
// two triangles.  Self-filtering takes a closed mesh as the solid it
// bounds and an open one as its convex hull.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace octoprox {

bool mesh_is_closed(const std::vector<std::array<uint32_t, 3>> &triangles);

}  // namespace octoprox
