#include "self_filter/padded_robot.hpp"

#include "self_filter/hull_vertices.hpp"
#include "self_filter/mesh_solid.hpp"
#include "self_filter/ray_entry.hpp"
#include "self_filter/solid_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {
namespace {

// A ball holding the padded shape: its box's, grown by robot_padding.
Ball bounding_ball(const PlacedShape &shape, double robot_padding) {
    return Ball{shape.box.center(), shape.box.half_extent().norm() + robot_padding};
}

// Whether the segment origin + t * dir, t in [0, t_max], meets the ball.
bool segment_meets(const Ball &ball, const Vec3 &origin, const Vec3 &dir, double t_max) {
    const Vec3 to_center = ball.center - origin;
    const double length2 = dir.squaredNorm();
    double t = length2 > 0.0 ? to_center.dot(dir) / length2 : 0.0;
    t = t < 0.0 ? 0.0 : (t > t_max ? t_max : t);
    return (to_center - t * dir).squaredNorm() <= ball.radius * ball.radius;
}

// Where the ray origin + t * dir first reaches the ball, t >= 0 (0 from
// inside it); infinity when it never does.
double ball_entry(const Ball &ball, const Vec3 &origin, const Vec3 &dir) {
    const Vec3 m = origin - ball.center;
    const double a = dir.squaredNorm(), b = m.dot(dir), c = m.squaredNorm() - ball.radius * ball.radius;
    if (c <= 0.0) return 0.0;
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0 || b >= 0.0) return std::numeric_limits<double>::infinity();
    return (-b - std::sqrt(discriminant)) / a;
}

// The core's box in the frame of core.center and core.axes (every kind
// but the sphere, whose ball is its box).
Aabb core_local_box(const PlacedShape &shape) {
    const ShapeDef &def = *shape.def;
    switch (def.kind) {
    case ShapeKind::kSphere: return Aabb();
    case ShapeKind::kCapsule: return Aabb::from_center(Vec3::Zero(), Vec3(0.0, 0.0, def.half_length));
    case ShapeKind::kBox: return Aabb::from_center(Vec3::Zero(), def.half_size);
    case ShapeKind::kCylinder: return Aabb::from_center(Vec3::Zero(), Vec3(def.radius, def.radius, def.half_length));
    case ShapeKind::kConvex: {
        Aabb box;
        for (const Vec3 &v : def.vertices) box.grow(v);
        return box;
    }
    case ShapeKind::kMesh: return def.mesh_tree.node(def.mesh_tree.root()).box;  // its triangles' box
    }
    return Aabb();
}

FilterSolid solid_of(const PlacedShape &shape, const LinkSet &robot, double robot_padding) {
    FilterSolid solid;
    solid.shape = &shape;
    solid.core = shape.core;
    solid.radius = shape.inflation + robot_padding;
    const double link_padding = robot.padding() + robot.link(shape.link).padding;
    solid.solid_radius = std::max(0.0, shape.inflation - link_padding);
    solid.local_box = core_local_box(shape);
    if (!solid.local_box.empty()) solid.local_box.inflate(solid.radius + kEntryTouch);
    if (shape.kind == ShapeKind::kMesh) {
        shape.place_mesh();
        solid.closed_mesh = shape.def->closed;
        if (solid.closed_mesh)
            solid.faces = shape.def->faces.get([&] { return build_mesh_faces(shape.def->vertices, shape.def->triangles); });
    }
    return solid;
}

// A hull's points placed at the shape's pose: the hull's vertices among
// the shape's (hull_vertices.hpp), found once per shape.
std::vector<Vec3> hull_local_vertices(const ShapeDef &def) {
    return def.hull_vertices.get([&] { return hull_vertex_superset(def.vertices); });
}

std::vector<Vec3> placed_hull(const PlacedShape &shape) {
    const std::vector<Vec3> local = hull_local_vertices(*shape.def);
    std::vector<Vec3> placed(local.size());
    for (size_t i = 0; i < local.size(); ++i) placed[i] = shape.core.axes * local[i] + shape.core.center;
    return placed;
}

}  // namespace

bool FilterSolid::may_meet(const Vec3 &origin, const Vec3 &dir, double t_max) const {
    if (local_box.empty()) return true;
    const Vec3 o = core.axes.transpose() * (origin - core.center), d = core.axes.transpose() * dir;
    double t0 = 0.0, t1 = t_max;
    return segment_in_box(local_box, o, d, t0, t1);
}

bool FilterSolid::holds(const Vec3 &x, double grow) const {
    if (closed_mesh) return MeshSolid(*shape, grow).holds(x);
    return grown_core_holds(core, grow, x);
}

double FilterSolid::entry(const Vec3 &origin, const Vec3 &dir, double t_max) const {
    if (closed_mesh)
        return grown_faces_entry(*faces, shape->core, radius, origin, dir, t_max);
    if (hull_faces) return grown_faces_entry(*hull_faces, core, radius, origin, dir, t_max);
    if (has_closed_form_entry(core)) return closed_form_entry(core, radius + kEntryTouch, origin, dir, t_max);
    return grown_core_entry(core, radius, origin, dir, t_max);
}

PaddedRobot::PaddedRobot(const LinkSet &robot, double robot_padding, const Vec3 &origin) : origin_(origin) {
    for (const PlacedShape &shape : robot.placed()) {
        if (shape.box.empty()) continue;  // a disabled link's
        if (shape.kind == ShapeKind::kMesh && shape.def->triangles.empty()) continue;
        FilterSolid solid = solid_of(shape, robot, robot_padding);
        if (shape.kind == ShapeKind::kConvex || (shape.kind == ShapeKind::kMesh && !solid.closed_mesh)) {
            // The core points into hulls_' inner vector, whose buffer stays
            // where it is when hulls_ grows (its vectors are moved).
            hulls_.push_back(placed_hull(shape));
            solid.hull_faces = shape.def->hull_faces.get([&] { return build_hull_faces(hull_local_vertices(*shape.def)); });
            solid.core.kind = ConvexKind::kHull;
            solid.core.hull = hulls_.back().data();
            solid.core.hull_count = hulls_.back().size();
        }
        solid.holds_origin = solid.holds(origin, solid.radius);
        solids_.push_back(solid);
        balls_.push_back(bounding_ball(shape, robot_padding));
    }
    bins_.build(origin, balls_);
}

void PaddedRobot::consider(uint32_t index, const Vec3 &end, const Vec3 &dir, bool end_is_point, double &best_t,
                           bool &entered, bool &on_robot) const {
    const FilterSolid &solid = solids_[index];
    const Ball &ball = balls_[index];
    if (end_is_point && !on_robot && (end - ball.center).squaredNorm() <= ball.radius * ball.radius)
        on_robot = solid.holds(end, solid.radius);
    if (solid.holds_origin || !segment_meets(ball, origin_, dir, best_t) || !solid.may_meet(origin_, dir, best_t))
        return;
    const double t = solid.entry(origin_, dir, best_t);
    if (t >= 0.0) best_t = t, entered = true;
}

RayCut PaddedRobot::cut(const Vec3 &end, bool end_is_point) const {
    const Vec3 dir = end - origin_;
    RayCut cut;
    if (solids_.empty() || dir == Vec3::Zero()) {
        if (end_is_point)  // a point at the sensor: inside the robot only if a solid holds it
            for (const FilterSolid &solid : solids_)
                if (solid.holds(end, solid.radius)) return RayCut{RayCut::kOnRobot, 0.0};
        return cut;
    }
    const uint32_t *first, *last;
    bins_.candidates(dir, first, last);
    // The candidates in the order the ray reaches their balls: an entry
    // found early cuts the ray short for the solids behind it.
    Candidate order[kOrdered];
    size_t count = 0;
    bool ordered = true;
    const auto add = [&](uint32_t index) {
        if (count == kOrdered) ordered = false;
        if (ordered) order[count++] = Candidate{ball_entry(balls_[index], origin_, dir), index};
    };
    for (const uint32_t *at = first; at != last; ++at) add(*at);
    for (const uint32_t index : bins_.everywhere()) add(index);
    double best_t = 1.0;
    bool entered = false, on_robot = false;
    if (ordered) {
        std::sort(order, order + count, [](const Candidate &a, const Candidate &b) { return a.t0 < b.t0; });
        for (size_t i = 0; i < count; ++i) consider(order[i].index, end, dir, end_is_point, best_t, entered, on_robot);
    } else {
        for (; first != last; ++first) consider(*first, end, dir, end_is_point, best_t, entered, on_robot);
        for (const uint32_t index : bins_.everywhere()) consider(index, end, dir, end_is_point, best_t, entered, on_robot);
    }
    if (on_robot) return RayCut{RayCut::kOnRobot, entered ? best_t : 0.0};
    if (entered) return RayCut{RayCut::kShadowed, best_t};
    return cut;
}

}  // namespace octoprox
