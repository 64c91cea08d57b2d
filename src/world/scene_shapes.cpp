#include "world/scene_shapes.hpp"

#include "base/bounds.hpp"
#include "base/error.hpp"
#include "robot/mesh_vertices.hpp"

#include <cmath>

namespace octoprox {
namespace {

void require_length(double value, const char *what, const SceneWhere &where) {
    if (!(value > 0.0) || !(value <= kMaxMetres))
        scene_fail(where, format("%s %g is not a positive length of at most %g m", what, value, kMaxMetres));
}

// Finite and within +-kMaxMetres on every axis.
bool within_bounds(const Vec3 &point) {
    return std::fabs(point.x()) <= kMaxMetres && std::fabs(point.y()) <= kMaxMetres && std::fabs(point.z()) <= kMaxMetres;
}

}  // namespace

ShapeDef scene_box(const Vec3 &size, const SceneWhere &where) {
    for (int axis = 0; axis < 3; ++axis) require_length(size[axis], "box size", where);
    ShapeDef def;
    def.kind = ShapeKind::kBox;
    def.half_size = 0.5 * size;
    return def;
}

ShapeDef scene_sphere(double radius, const SceneWhere &where) {
    require_length(radius, "sphere radius", where);
    ShapeDef def;
    def.kind = ShapeKind::kSphere;
    def.radius = radius;
    return def;
}

ShapeDef scene_cylinder(double radius, double length, const SceneWhere &where) {
    require_length(radius, "cylinder radius", where);
    require_length(length, "cylinder length", where);
    ShapeDef def;
    def.kind = ShapeKind::kCylinder;
    def.radius = radius;
    def.half_length = 0.5 * length;
    return def;
}

ShapeDef scene_mesh(std::vector<Vec3> vertices, std::vector<std::array<uint32_t, 3>> triangles,
                    const SceneWhere &where) {
    if (triangles.empty()) scene_fail(where, "a mesh needs at least one triangle");
    for (size_t i = 0; i < vertices.size(); ++i)
        if (!within_bounds(vertices[i]))
            scene_fail(where, format("vertex %zu is not finite within +-%g m", i, kMaxMetres));
    for (size_t t = 0; t < triangles.size(); ++t)
        for (uint32_t index : triangles[t])
            if (index >= vertices.size())
                scene_fail(where, format("triangle %zu uses vertex %u; the mesh has %zu vertices", t, index,
                                         vertices.size()));
    ShapeDef def;
    def.kind = ShapeKind::kMesh;
    keep_used_vertices(vertices, triangles, VertexWeld::kNone);
    def.vertices = std::move(vertices);
    def.triangles = std::move(triangles);
    return def;
}

Pose scene_pose(const Vec3 &position, const std::array<double, 4> &q, const SceneWhere &where) {
    if (!within_bounds(position)) scene_fail(where, format("the position is not finite within +-%g m", kMaxMetres));
    for (double value : q)
        if (!std::isfinite(value)) scene_fail(where, "the orientation is not finite");
    const double norm2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    const bool zero = norm2 == 0.0;
    // As the C ABI's poses: a quaternion this short is no rotation to normalise.
    if (!zero && norm2 < 1e-12) scene_fail(where, "the orientation is almost a zero quaternion");
    const double identity[4] = {0.0, 0.0, 0.0, 1.0};
    const double xyz[3] = {position.x(), position.y(), position.z()};
    return pose_from_ros(xyz, zero ? identity : q.data());
}

}  // namespace octoprox
