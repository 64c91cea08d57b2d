// A minimal binary STL reader (80-byte header, uint32 triangle count, then
// 50 bytes per triangle: normal, three vertices as little-endian float32,
// and a 16-bit attribute).  Vertices are not merged: three per triangle.
#pragma once

#include "oracle_geometry.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace oracle {

struct StlMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<uint32_t, 3>> triangles;
};

// false (and `error` set) when the file cannot be read or is not a
// well-formed binary STL.
bool read_binary_stl(const std::string &path, StlMesh &mesh, std::string &error);

}  // namespace oracle
