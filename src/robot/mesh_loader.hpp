// Triangle meshes from files (STL, DAE, OBJ and whatever else assimp
// reads): every mesh of the file merged into one, node transforms applied.
#pragma once

#include "geometry/pose.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace octoprox {

struct TriangleMesh {
    std::vector<Vec3> vertices;  // only vertices some triangle uses
    std::vector<std::array<uint32_t, 3>> triangles;
};

// Throws ApiError: OPX_ERROR_IO when the file cannot be read,
// OPX_ERROR_CORRUPT when assimp rejects it or it has no triangles.
TriangleMesh load_mesh_file(const std::string &path);

// The mesh with each vertex scaled per axis (URDF <mesh scale>).
TriangleMesh scaled(const TriangleMesh &mesh, const Vec3 &scale);

}  // namespace octoprox
