#include "robot/shape.hpp"

#include "robot/mesh_bounds.hpp"
#include "robot/mesh_closure.hpp"

namespace octoprox {
namespace {

Aabb triangle_box(const Vec3 &a, const Vec3 &b, const Vec3 &c) {
    Aabb box;
    box.grow(a), box.grow(b), box.grow(c);
    return box;
}

// Into `boxes`, whose capacity is reused: placing a mesh again allocates nothing.
void triangle_boxes(const std::vector<Vec3> &vertices, const std::vector<std::array<uint32_t, 3>> &triangles,
                    std::vector<Aabb> &boxes) {
    boxes.clear();
    for (const auto &t : triangles) boxes.push_back(triangle_box(vertices[t[0]], vertices[t[1]], vertices[t[2]]));
}

// A mesh's shape-frame box placed, padded as placed_union pads.
Aabb placed_local_box(const Convex &core, const Aabb &local) {
    Aabb placed = Aabb::from_center(core.axes * local.center() + core.center,
                                    core.axes.cwiseAbs() * local.half_extent());
    pad_placed_box(placed, core.center);
    return placed;
}

// Bounds of the core in the map frame, before inflation.
Aabb core_box(const PlacedShape &s, const ShapeDef &def, MeshBox mesh_box) {
    const Convex &core = s.core;
    switch (def.kind) {
    case ShapeKind::kSphere: return Aabb::from_center(core.center, Vec3::Zero());
    case ShapeKind::kCapsule: return triangle_box(core.v[0], core.v[1], core.v[1]);
    case ShapeKind::kBox: return Aabb::from_center(core.center, core.axes.cwiseAbs() * core.half);
    case ShapeKind::kCylinder: {
        const Vec3 axis = core.axes.col(2);
        Vec3 half;
        for (int i = 0; i < 3; ++i)
            half[i] = core.half.z() * std::fabs(axis[i]) +
                      core.half.x() * std::sqrt(std::max(0.0, 1.0 - axis[i] * axis[i]));
        return Aabb::from_center(core.center, half);
    }
    case ShapeKind::kConvex: {
        Aabb box;
        for (const Vec3 &v : s.world_vertices) box.grow(v);
        return box;
    }
    case ShapeKind::kMesh:
        return mesh_box == MeshBox::kCheap && !def.local_box.empty() ? placed_local_box(core, def.local_box)
                                                                     : placed_union(def.bounds, core.axes, core.center);
    }
    return Aabb();
}

}  // namespace

void build_mesh_tree(ShapeDef &def) {
    std::vector<Aabb> boxes;
    triangle_boxes(def.vertices, def.triangles, boxes);
    def.mesh_tree.build(boxes);
    def.closed = mesh_is_closed(def.triangles);
    // Few vertices: the exact box costs about as much as the frontier's.
    def.bounds = def.vertices.size() > kExactBoxVertices ? box_columns(mesh_frontier_boxes(def.mesh_tree))
                                                         : point_columns(def.vertices);
    def.local_box = Aabb();
    if (def.mesh_tree.empty()) return;
    const Aabb &local = def.mesh_tree.node(def.mesh_tree.root()).box;
    if (rotated_box_looseness(local, def.vertices) <= kCheapBoxLooseness) def.local_box = local;
}

void PlacedShape::place_mesh() const {
    if (mesh_placement.done.load(std::memory_order_acquire)) return;
    std::lock_guard<std::mutex> guard(mesh_placement.lock);
    if (mesh_placement.done.load(std::memory_order_relaxed)) return;
    world_vertices.resize(def->vertices.size());
    for (size_t i = 0; i < def->vertices.size(); ++i) world_vertices[i] = core.axes * def->vertices[i] + core.center;
    if (mesh_tree.size() != def->mesh_tree.size()) mesh_tree = def->mesh_tree;
    triangle_boxes(world_vertices, def->triangles, triangle_box_scratch);
    mesh_tree.refit(triangle_box_scratch);
    mesh_vertex_box = Aabb();
    for (const Vec3 &v : world_vertices) mesh_vertex_box.grow(v);
    mesh_placement.done.store(true, std::memory_order_release);
}

Aabb PlacedShape::exact_box() const {
    if (kind != ShapeKind::kMesh || box.empty()) return box;
    place_mesh();
    Aabb exact = mesh_vertex_box;
    exact.inflate(inflation);
    return exact;
}

Convex PlacedShape::posed_triangle(int32_t index) const {
    const auto &t = def->triangles[index];
    Convex c;
    c.kind = ConvexKind::kTriangle;
    for (int k = 0; k < 3; ++k) c.v[k] = core.axes * def->vertices[t[k]] + core.center;
    return c;
}

Convex PlacedShape::triangle(int32_t index) const {
    const auto &t = def->triangles[index];
    Convex c;
    c.kind = ConvexKind::kTriangle;
    c.v[0] = world_vertices[t[0]], c.v[1] = world_vertices[t[1]], c.v[2] = world_vertices[t[2]];
    return c;
}

namespace {

// A sphere is a point core and a radius: its placement needs the centre
// alone (no rotation is composed; its axes are never read), and it is
// placed for every robot pose of a sphere-based robot.
void place_sphere(const ShapeDef &def, const Pose &link_pose, double padding, bool enabled, PlacedShape &out) {
    out.def = &def;
    out.kind = ShapeKind::kSphere;
    out.inflation = padding + def.radius;
    out.core.kind = ConvexKind::kPoint;
    out.core.center = link_pose.apply(def.local.translation);
    out.box = enabled ? Aabb::from_center(out.core.center, Vec3::Constant(out.inflation)) : Aabb();
}

}  // namespace

void place_shape(const ShapeDef &def, const Pose &link_pose, double padding, bool enabled, PlacedShape &out,
                 MeshBox mesh_box) {
    if (def.kind == ShapeKind::kSphere) return place_sphere(def, link_pose, padding, enabled, out);
    // Most shapes sit unturned at their link's origin (42 and 53 of the
    // PR2's 54): the link's own rotation and origin are what the products
    // give them (a zero's sign aside), and a batch places every shape of a
    // moved link for each configuration.
    const Eigen::Matrix3d rotation =
        def.local.rotation == Eigen::Matrix3d::Identity() ? link_pose.rotation : link_pose.rotation * def.local.rotation;
    const Vec3 center = def.local.translation.isZero(0.0) ? link_pose.translation : link_pose.apply(def.local.translation);
    // A shape placed again rewrites every field its kind reads: only a
    // slot taking another shape starts from a clean core.
    if (out.def != &def) out.core = Convex();
    out.def = &def;
    out.kind = def.kind;
    out.inflation = padding;
    out.core.center = center;
    out.core.axes = rotation;
    switch (def.kind) {
    case ShapeKind::kSphere:
        out.core.kind = ConvexKind::kPoint;
        out.inflation += def.radius;
        break;
    case ShapeKind::kCapsule:
        out.core.kind = ConvexKind::kSegment;
        out.core.v[0] = center - def.half_length * rotation.col(2);
        out.core.v[1] = center + def.half_length * rotation.col(2);
        out.inflation += def.radius;
        break;
    case ShapeKind::kBox:
        out.core.kind = ConvexKind::kBox;
        out.core.half = def.half_size;
        break;
    case ShapeKind::kCylinder:
        out.core.kind = ConvexKind::kCylinder;
        out.core.half = Vec3(def.radius, def.radius, def.half_length);
        break;
    case ShapeKind::kConvex:
        out.world_vertices.resize(def.vertices.size());
        for (size_t i = 0; i < def.vertices.size(); ++i)
            out.world_vertices[i] = rotation * def.vertices[i] + center;
        out.core.kind = ConvexKind::kHull;
        out.core.hull = out.world_vertices.data();
        out.core.hull_count = out.world_vertices.size();
        break;
    case ShapeKind::kMesh:
        out.core.kind = ConvexKind::kHull;  // never read as a whole: queries go through the triangles
        out.mesh_placement.done.store(false, std::memory_order_release);
        break;
    }
    out.box = Aabb();
    if (enabled) {
        out.box = core_box(out, def, mesh_box);
        out.box.inflate(out.inflation);
    }
}

}  // namespace octoprox
