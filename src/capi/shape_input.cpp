#include "capi/shape_input.hpp"

#include "base/bounds.hpp"
#include "capi/checks.hpp"
#include "robot/mesh_vertices.hpp"

namespace octoprox::capi {
namespace {

std::vector<Vec3> read_vertices(const opx_shape &shape) {
    if (shape.vertex_count == 0) throw_invalid("shape->vertex_count is 0");
    require_pointer(shape.vertices, "shape->vertices");
    const size_t stride = shape.vertex_stride == 0 ? 3 * sizeof(double) : shape.vertex_stride;
    if (stride < 3 * sizeof(double))
        throw_invalid(format("shape->vertex_stride %zu is smaller than one vertex (24 bytes)", stride));
    std::vector<Vec3> vertices(shape.vertex_count);
    const auto *bytes = reinterpret_cast<const unsigned char *>(shape.vertices);
    for (size_t i = 0; i < shape.vertex_count; ++i) {
        double xyz[3];
        std::memcpy(xyz, bytes + i * stride, sizeof xyz);
        for (int axis = 0; axis < 3; ++axis)
            if (!(std::fabs(xyz[axis]) <= kMaxMetres))
                throw_invalid(format("shape->vertices[%zu] is %g on axis %d; vertices are within +-%g m", i,
                                     xyz[axis], axis, kMaxMetres));
        vertices[i] = Vec3(xyz[0], xyz[1], xyz[2]);
    }
    return vertices;
}

std::vector<std::array<uint32_t, 3>> read_triangles(const opx_shape &shape) {
    if (shape.triangle_count == 0) throw_invalid("shape->triangle_count is 0");
    require_pointer(shape.indices, "shape->indices");
    std::vector<std::array<uint32_t, 3>> triangles(shape.triangle_count);
    for (size_t t = 0; t < shape.triangle_count; ++t) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = shape.indices[3 * t + k];
            if (index >= shape.vertex_count)
                throw_invalid(format("shape->indices[%zu] is %u, beyond vertex_count %zu", 3 * t + k,
                                     index, shape.vertex_count));
            triangles[t][k] = index;
        }
    }
    return triangles;
}

}  // namespace

void require_positive(double value, const char *argument) {
    if (!(value > 0.0) || !(value <= kMaxMetres))
        throw_invalid(format("%s is %g; a positive length of at most %g m is needed", argument, value, kMaxMetres));
}

void require_position_in_bounds(const Pose &pose, const char *argument) {
    for (int axis = 0; axis < 3; ++axis)
        if (!(std::fabs(pose.translation[axis]) <= kMaxMetres))
            throw_invalid(format("%s.position[%d] is %g; positions are within +-%g m", argument, axis,
                                 pose.translation[axis], kMaxMetres));
}

void require_padding(double value, const char *argument) {
    if (!(value >= 0.0) || !std::isfinite(value))
        throw_invalid(format("%s is %g; a padding is a finite length >= 0 in metres", argument, value));
}

ShapeDef read_shape(const opx_shape *in) {
    opx_shape shape = OPX_SHAPE_INIT;
    require_pointer(in, "shape");
    read_versioned(in, shape, "shape");
    ShapeDef def;
    def.local = read_pose(shape.pose, "shape->pose");
    require_position_in_bounds(def.local, "shape->pose");
    switch (shape.kind) {
    case OPX_SHAPE_SPHERE: require_positive(shape.radius, "shape->radius"); break;
    case OPX_SHAPE_BOX:
        for (int axis = 0; axis < 3; ++axis) require_positive(shape.size[axis], "shape->size[i]");
        def.half_size = 0.5 * Vec3(shape.size[0], shape.size[1], shape.size[2]);
        break;
    case OPX_SHAPE_CYLINDER:
        require_positive(shape.radius, "shape->radius");
        require_positive(shape.length, "shape->length");
        break;
    case OPX_SHAPE_CAPSULE:
        require_positive(shape.radius, "shape->radius");
        if (shape.length != 0.0) require_positive(shape.length, "shape->length");  // 0: a sphere
        break;
    case OPX_SHAPE_CONVEX: def.vertices = read_vertices(shape); break;
    case OPX_SHAPE_MESH:
        def.vertices = read_vertices(shape);
        def.triangles = read_triangles(shape);
        keep_used_vertices(def.vertices, def.triangles, VertexWeld::kNone);
        break;
    default: throw_invalid(format("shape->kind %d is not an OPX_SHAPE_* kind (1..6)", shape.kind));
    }
    def.kind = static_cast<ShapeKind>(shape.kind);
    def.radius = shape.radius;
    def.half_length = 0.5 * shape.length;
    return def;
}

opx_shape shape_to_abi(const ShapeDef &def) {
    opx_shape out = OPX_SHAPE_INIT;
    const Eigen::Quaterniond q(def.local.rotation);
    out.kind = static_cast<int32_t>(def.kind);
    out.pose = opx_pose{{def.local.translation.x(), def.local.translation.y(), def.local.translation.z()},
                        {q.x(), q.y(), q.z(), q.w()}};
    out.radius = def.radius;
    out.length = 2.0 * def.half_length;
    for (int axis = 0; axis < 3; ++axis) out.size[axis] = 2.0 * def.half_size[axis];
    static_assert(sizeof(Vec3) == 3 * sizeof(double), "vertices are packed triples");
    static_assert(sizeof(std::array<uint32_t, 3>) == 3 * sizeof(uint32_t), "indices are packed triples");
    if (!def.vertices.empty()) {
        out.vertices = def.vertices.front().data();
        out.vertex_count = def.vertices.size();
    }
    if (!def.triangles.empty()) {
        out.indices = def.triangles.front().data();
        out.triangle_count = def.triangles.size();
    }
    return out;
}

}  // namespace octoprox::capi
