// A mesh's vertex list kept to what its triangles use: the rule shared by
// meshes given through the C ABI and meshes read from files.
#pragma once

#include "geometry/pose.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace octoprox {

enum class VertexWeld {
    kNone,          // every used vertex stays, even at the position of another
    kSamePosition,  // vertices at the same position (-0 as +0) become one
};

// Drops the vertices no triangle uses (they would only widen the mesh's
// bounds, and so its cost boxes) and renumbers the triangles' indices in
// the order of first use.  kSamePosition also welds equal positions: files
// split a corner by normal or colour, and every pose update would place
// each copy.  Indices must be below vertices.size().
void keep_used_vertices(std::vector<Vec3> &vertices, std::vector<std::array<uint32_t, 3>> &triangles,
                        VertexWeld weld);

}  // namespace octoprox
