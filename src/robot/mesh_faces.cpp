#include "robot/mesh_faces.hpp"

#include "geometry/convex_hull.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace octoprox {
namespace {

// An edge is left untested only when the other face's far vertex lies
// above the owning face's outward plane by more than this share of its
// distance from the edge: flat and nearly flat edges keep their cylinder.
constexpr double kConcaveMargin = 1e-9;

uint64_t directed_key(uint32_t a, uint32_t b) { return (uint64_t{a} << 32) | b; }
uint64_t edge_key(uint32_t a, uint32_t b) { return directed_key(std::min(a, b), std::max(a, b)); }

// Every directed edge once and its reverse once: the faces all turn the
// same way round the solid.
bool consistently_oriented(const std::vector<std::array<uint32_t, 3>> &triangles) {
    std::vector<uint64_t> directed;
    directed.reserve(3 * triangles.size());
    for (const auto &t : triangles)
        for (int k = 0; k < 3; ++k) directed.push_back(directed_key(t[k], t[(k + 1) % 3]));
    std::sort(directed.begin(), directed.end());
    if (std::adjacent_find(directed.begin(), directed.end()) != directed.end()) return false;
    for (const uint64_t key : directed)
        if (!std::binary_search(directed.begin(), directed.end(), (key << 32) | (key >> 32))) return false;
    return true;
}

MeshFace face_of(const std::vector<Vec3> &vertices, const std::array<uint32_t, 3> &t) {
    MeshFace face;
    for (int k = 0; k < 3; ++k) face.v[k] = vertices[t[k]];
    const Vec3 cross = (face.v[1] - face.v[0]).cross(face.v[2] - face.v[0]);
    face.area2 = cross.norm();
    if (face.area2 > 0.0) face.normal = cross / face.area2;
    face.offset = face.normal.dot(face.v[0]);
    const Vec3 lo = face.v[0].cwiseMin(face.v[1]).cwiseMin(face.v[2]), hi = face.v[0].cwiseMax(face.v[1]).cwiseMax(face.v[2]);
    face.centre = 0.5 * (lo + hi);
    for (const Vec3 &v : face.v) face.reach = std::max(face.reach, (v - face.centre).norm());
    return face;
}

// Whether the edge k of `owner` is clearly concave, `far` being the other
// face's vertex off the edge and `outward` +1 or -1 (the faces' turn).
bool clearly_concave(const MeshFace &owner, int k, const Vec3 &far, double outward) {
    if (owner.area2 == 0.0) return false;
    const Vec3 &a = owner.v[k];
    const double height = outward * owner.normal.dot(far - a);
    return height > kConcaveMargin * (far - a).norm();
}

Aabb face_box(const MeshFace &face) {
    Aabb box;
    for (const Vec3 &v : face.v) box.grow(v);
    return box;
}

// Splits faces [first, first + count) at the median of their centres
// along the box's longest axis until a run fits a leaf; returns the node.
int32_t build_node(std::vector<MeshFace> &faces, uint32_t first, uint32_t count, std::vector<FaceNode> &nodes) {
    const int32_t index = int32_t(nodes.size());
    nodes.emplace_back();
    Aabb box;
    for (uint32_t i = first; i < first + count; ++i) box.grow(face_box(faces[i]));
    nodes[index].box = box;
    if (count <= kFacesPerLeaf) {
        nodes[index].first = first, nodes[index].count = count;
        return index;
    }
    int axis = 0;
    const Vec3 size = box.hi - box.lo;
    if (size.y() > size[axis]) axis = 1;
    if (size.z() > size[axis]) axis = 2;
    const auto centre = [axis](const MeshFace &f) { return f.v[0][axis] + f.v[1][axis] + f.v[2][axis]; };
    const uint32_t half = count / 2;
    std::nth_element(faces.begin() + first, faces.begin() + first + half, faces.begin() + first + count,
                     [&](const MeshFace &a, const MeshFace &b) { return centre(a) < centre(b); });
    const int32_t left = build_node(faces, first, half, nodes);
    const int32_t right = build_node(faces, first + half, count - half, nodes);
    nodes[index].left = left, nodes[index].right = right;
    return index;
}

}  // namespace

std::shared_ptr<const MeshFaces> build_mesh_faces(const std::vector<Vec3> &vertices,
                                                  const std::vector<std::array<uint32_t, 3>> &triangles) {
    auto result = std::make_shared<MeshFaces>();
    std::vector<MeshFace> *faces = &result->faces;
    faces->reserve(triangles.size());
    double volume6 = 0.0;
    for (const auto &t : triangles) {
        faces->push_back(face_of(vertices, t));
        volume6 += vertices[t[0]].dot(vertices[t[1]].cross(vertices[t[2]]));
    }
    const bool oriented = consistently_oriented(triangles);
    const double outward = volume6 >= 0.0 ? 1.0 : -1.0;
    std::unordered_map<uint64_t, std::pair<uint32_t, int>> owners;  // edge: its first face and that face's k
    std::vector<bool> vertex_owned(vertices.size(), false);
    owners.reserve(2 * triangles.size());
    for (uint32_t f = 0; f < triangles.size(); ++f) {
        const auto &t = triangles[f];
        MeshFace &face = (*faces)[f];
        for (int k = 0; k < 3; ++k) {
            if (!vertex_owned[t[k]]) vertex_owned[t[k]] = true, face.vertices |= uint8_t(1u << k);
            const auto found = owners.emplace(edge_key(t[k], t[(k + 1) % 3]), std::make_pair(f, k));
            if (found.second) {
                face.edges |= uint8_t(1u << k);
                continue;
            }
            // The second face of the edge: the owner's test goes when the
            // two meet clearly concave and neither is degenerate.
            const auto [owner, owner_k] = found.first->second;
            MeshFace &first = (*faces)[owner];
            if (oriented && face.area2 > 0.0 && clearly_concave(first, owner_k, vertices[t[(k + 2) % 3]], outward))
                first.edges &= uint8_t(~(1u << owner_k));
        }
    }
    if (!faces->empty()) build_node(*faces, 0, uint32_t(faces->size()), result->nodes);
    return result;
}

std::shared_ptr<const MeshFaces> build_hull_faces(const std::vector<Vec3> &vertices) {
    HullMesh hull;
    if (!convex_hull(vertices, hull)) return nullptr;
    return build_mesh_faces(hull.vertices, hull.triangles);
}

}  // namespace octoprox
