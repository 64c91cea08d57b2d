#include "robot/mesh_loader.hpp"

#include "base/error.hpp"
#include "robot/mesh_vertices.hpp"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <array>
#include <cmath>
#include <fstream>
#include <utility>
#include <vector>

namespace octoprox {
namespace {

Eigen::Matrix4d to_eigen(const aiMatrix4x4 &m) {
    Eigen::Matrix4d out;
    out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3, m.d4;
    return out;
}

// Appends the triangles of one assimp mesh, its vertices taken to the
// file's root frame by `transform`.  Indices are checked: a hostile file
// must not make a triangle point outside its mesh.
void append_mesh(const aiMesh &mesh, const Eigen::Matrix4d &transform, const std::string &path, TriangleMesh &out) {
    if (out.vertices.size() + mesh.mNumVertices > UINT32_MAX)
        throw_corrupt("mesh file '" + path + "' has more than 2^32 vertices");
    const uint32_t first = static_cast<uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D &p = mesh.mVertices[v];
        out.vertices.push_back((transform * Eigen::Vector4d(p.x, p.y, p.z, 1.0)).head<3>());
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace &face = mesh.mFaces[f];
        if (face.mNumIndices != 3) continue;  // points and lines are no surface
        for (unsigned k = 0; k < 3; ++k)
            if (face.mIndices[k] >= mesh.mNumVertices)
                throw_corrupt("mesh file '" + path + "' has a face whose vertex index is out of range");
        out.triangles.push_back({first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
    }
}

// Every mesh of the node tree in its node's frame, in depth-first order
// (a node's meshes, then its children's).  Iterative: a file may
// nest nodes deeper than a thread's stack would take.
void append_nodes(const aiScene &scene, const std::string &path, TriangleMesh &out) {
    std::vector<std::pair<const aiNode *, Eigen::Matrix4d>> pending{{scene.mRootNode, Eigen::Matrix4d::Identity()}};
    while (!pending.empty()) {
        const aiNode &node = *pending.back().first;
        const Eigen::Matrix4d transform = pending.back().second * to_eigen(node.mTransformation);
        pending.pop_back();
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            if (node.mMeshes[i] >= scene.mNumMeshes)
                throw_corrupt("mesh file '" + path + "' has a node naming a mesh that does not exist");
            append_mesh(*scene.mMeshes[node.mMeshes[i]], transform, path, out);
        }
        // Reversed onto the stack: the children come out in the file's order.
        for (unsigned i = node.mNumChildren; i-- > 0;) pending.emplace_back(node.mChildren[i], transform);
    }
}

}  // namespace

TriangleMesh load_mesh_file(const std::string &path) {
    if (!std::ifstream(path, std::ios::binary).good())
        throw ApiError(OPX_ERROR_IO, "mesh file '" + path + "' cannot be read");
    Assimp::Importer importer;
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    // assimp would turn a Z_UP Collada file to its own Y-up convention; ROS
    // (URDF, RViz, MoveIt) keeps mesh coordinates as written, z up.  The
    // <unit> scale is still applied (to the root node, which we honour).
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
    const aiScene *scene = importer.ReadFile(
        path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType);
    if (scene == nullptr || scene->mRootNode == nullptr)
        throw_corrupt("mesh file '" + path + "' cannot be imported: " + importer.GetErrorString());
    TriangleMesh mesh;
    append_nodes(*scene, path, mesh);
    if (mesh.triangles.empty()) throw_corrupt("mesh file '" + path + "' has no triangles");
    keep_used_vertices(mesh.vertices, mesh.triangles, VertexWeld::kSamePosition);
    for (const Vec3 &v : mesh.vertices)
        if (!v.allFinite()) throw_corrupt("mesh file '" + path + "' has a vertex that is not finite");
    return mesh;
}

TriangleMesh scaled(const TriangleMesh &mesh, const Vec3 &scale) {
    TriangleMesh out = mesh;
    for (Vec3 &v : out.vertices) v = v.cwiseProduct(scale);
    return out;
}

}  // namespace octoprox
