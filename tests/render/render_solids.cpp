#include "render_solids.hpp"

#include <algorithm>
#include <cmath>

namespace render {
namespace {

// The part [t0, t1] of a ray inside a convex solid, maybe empty.
struct Span {
    double t0 = -kNoHit, t1 = kNoHit;
    bool empty() const { return !(t0 <= t1); }
    void clip(double a, double b) { t0 = std::max(t0, a), t1 = std::min(t1, b); }
    void clear() { t0 = kNoHit, t1 = -kNoHit; }
};

// The entry of a ray that starts outside the solid (the span's start).
double entry(const Span &span) { return span.empty() || !(span.t0 > 0.0) ? kNoHit : span.t0; }

// Roots of a t^2 + 2 b t + c = 0 (a > 0), ascending; false when none.  The
// smaller-magnitude root is computed as c / q to avoid cancellation.
bool quadratic_roots(double a, double b, double c, double &r0, double &r1) {
    const double disc = b * b - a * c;
    if (disc < 0.0) return false;
    const double q = -(b + std::copysign(std::sqrt(disc), b));
    if (q == 0.0) {
        r0 = r1 = 0.0;
        return true;
    }
    r0 = q / a, r1 = c / q;
    if (r0 > r1) std::swap(r0, r1);
    return true;
}

Span sphere_span(const Vec3 &center, double radius, const Vec3 &o, const Vec3 &d) {
    Span span;
    const Vec3 rel = o - center;
    double r0 = 0.0, r1 = 0.0;
    if (!quadratic_roots(d.squaredNorm(), rel.dot(d), rel.squaredNorm() - radius * radius, r0, r1)) span.clear();
    else span.clip(r0, r1);
    return span;
}

// The slab |o_i + t d_i| <= half on one axis.
void clip_slab(Span &span, double o, double d, double half) {
    if (d == 0.0) {
        if (std::fabs(o) > half) span.clear();
        return;
    }
    const double a = (-half - o) / d, b = (half - o) / d;
    span.clip(std::min(a, b), std::max(a, b));
}

Span box_span(const Vec3 &half, const Vec3 &o, const Vec3 &d) {
    Span span;
    for (int axis = 0; axis < 3; ++axis) clip_slab(span, o[axis], d[axis], half[axis]);
    return span;
}

// The cylinder of `radius` around z, |z| <= half_length.
Span cylinder_span(double radius, double half_length, const Vec3 &o, const Vec3 &d) {
    Span span;
    clip_slab(span, o.z(), d.z(), half_length);
    const double a = d.x() * d.x() + d.y() * d.y();
    const double c = o.x() * o.x() + o.y() * o.y() - radius * radius;
    if (a == 0.0) {
        if (c > 0.0) span.clear();
        return span;
    }
    double r0 = 0.0, r1 = 0.0;
    if (!quadratic_roots(a, o.x() * d.x() + o.y() * d.y(), c, r0, r1)) span.clear();
    else span.clip(r0, r1);
    return span;
}

Span hull_span(const std::vector<HalfSpace> &faces, const Vec3 &o, const Vec3 &d) {
    Span span;
    for (const HalfSpace &f : faces) {
        const double along = f.normal.dot(d), room = f.offset - f.normal.dot(o);
        if (along == 0.0) {
            if (room < 0.0) span.clear();
        } else if (along < 0.0) {
            span.clip(room / along, kNoHit);
        } else {
            span.clip(-kNoHit, room / along);
        }
    }
    return span;
}

// The corners of the box [-half, half] (shape frame) in the map frame.
std::vector<Vec3> box_corners(const Eigen::Isometry3d &pose, const Vec3 &half) {
    std::vector<Vec3> corners;
    for (int c = 0; c < 8; ++c)
        corners.push_back(pose * Vec3((c & 1 ? 1 : -1) * half.x(), (c & 2 ? 1 : -1) * half.y(),
                                      (c & 4 ? 1 : -1) * half.z()));
    return corners;
}

std::vector<Vec3> shape_vertices(const opx_shape &shape) {
    std::vector<Vec3> points;
    const size_t stride = shape.vertex_stride == 0 ? 3 * sizeof(double) : shape.vertex_stride;
    for (size_t i = 0; i < shape.vertex_count; ++i) {
        const double *v = reinterpret_cast<const double *>(reinterpret_cast<const char *>(shape.vertices) + i * stride);
        points.emplace_back(v[0], v[1], v[2]);
    }
    return points;
}

// The distance from `x` to the segment between (0, 0, -h) and (0, 0, h).
double distance_to_axis_segment(const Vec3 &x, double h) {
    return Vec3(x.x(), x.y(), x.z() - std::clamp(x.z(), -h, h)).norm();
}

}  // namespace

std::vector<HalfSpace> hull_faces(const std::vector<Vec3> &points) {
    double scale = 0.0;
    for (const Vec3 &p : points) scale = std::max(scale, p.cwiseAbs().maxCoeff());
    const double tolerance = 1e-12 * std::max(scale, 1.0);
    std::vector<HalfSpace> faces;
    const size_t n = points.size();
    for (size_t i = 0; i < n; ++i)
        for (size_t j = i + 1; j < n; ++j)
            for (size_t k = j + 1; k < n; ++k) {
                Vec3 normal = (points[j] - points[i]).cross(points[k] - points[i]);
                if (!(normal.norm() > tolerance)) continue;  // collinear
                normal.normalize();
                const double offset = normal.dot(points[i]);
                bool below = true, above = true;
                for (const Vec3 &p : points) {
                    const double s = normal.dot(p) - offset;
                    below = below && s <= tolerance, above = above && s >= -tolerance;
                }
                if (below) faces.push_back({normal, offset});
                if (above) faces.push_back({-normal, -offset});
            }
    return faces;
}

Primitive make_primitive(const opx_shape &shape, const Eigen::Isometry3d &map_from_shape) {
    Primitive p;
    p.kind = shape.kind;
    p.map_from_shape = map_from_shape;
    p.radius = shape.radius;
    switch (shape.kind) {
    case OPX_SHAPE_SPHERE: p.corners = box_corners(map_from_shape, Vec3::Constant(shape.radius)); break;
    case OPX_SHAPE_BOX:
        p.half_size = 0.5 * Vec3(shape.size[0], shape.size[1], shape.size[2]);
        p.corners = box_corners(map_from_shape, p.half_size);
        break;
    case OPX_SHAPE_CYLINDER:
    case OPX_SHAPE_CAPSULE: {
        p.half_length = 0.5 * shape.length;
        const double reach = p.half_length + (shape.kind == OPX_SHAPE_CAPSULE ? shape.radius : 0.0);
        p.corners = box_corners(map_from_shape, Vec3(shape.radius, shape.radius, reach));
        break;
    }
    case OPX_SHAPE_CONVEX: {
        const std::vector<Vec3> vertices = shape_vertices(shape);
        p.faces = hull_faces(vertices);
        for (const Vec3 &v : vertices) p.corners.push_back(map_from_shape * v);
        break;
    }
    default: break;
    }
    return p;
}

bool holds(const Primitive &solid, const Vec3 &x) {
    const Vec3 p = solid.map_from_shape.inverse() * x;
    switch (solid.kind) {
    case OPX_SHAPE_SPHERE: return p.norm() <= solid.radius;
    case OPX_SHAPE_BOX: return (p.cwiseAbs() - solid.half_size).maxCoeff() <= 0.0;
    case OPX_SHAPE_CYLINDER: return std::hypot(p.x(), p.y()) <= solid.radius && std::fabs(p.z()) <= solid.half_length;
    case OPX_SHAPE_CAPSULE: return distance_to_axis_segment(p, solid.half_length) <= solid.radius;
    case OPX_SHAPE_CONVEX:
        for (const HalfSpace &f : solid.faces)
            if (f.normal.dot(p) > f.offset) return false;
        return !solid.faces.empty();
    default: return false;
    }
}

double first_hit(const Primitive &solid, const Vec3 &origin, const Vec3 &dir) {
    if (holds(solid, origin)) return kNoHit;
    const Eigen::Isometry3d shape_from_map = solid.map_from_shape.inverse();
    const Vec3 o = shape_from_map * origin, d = shape_from_map.linear() * dir;
    switch (solid.kind) {
    case OPX_SHAPE_SPHERE: return entry(sphere_span(Vec3::Zero(), solid.radius, o, d));
    case OPX_SHAPE_BOX: return entry(box_span(solid.half_size, o, d));
    case OPX_SHAPE_CYLINDER: return entry(cylinder_span(solid.radius, solid.half_length, o, d));
    case OPX_SHAPE_CAPSULE: {
        // The union's entry is the first of its parts' entries.
        const Vec3 end(0.0, 0.0, solid.half_length);
        return std::min({entry(cylinder_span(solid.radius, solid.half_length, o, d)),
                         entry(sphere_span(end, solid.radius, o, d)), entry(sphere_span(-end, solid.radius, o, d))});
    }
    case OPX_SHAPE_CONVEX: return solid.faces.empty() ? kNoHit : entry(hull_span(solid.faces, o, d));
    default: return kNoHit;
    }
}

double triangle_hit(const Triangle &tri, const Vec3 &origin, const Vec3 &dir) {
    // Möller and Trumbore: barycentric (u, v) and t by Cramer's rule.
    const Vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a;
    const Vec3 p = dir.cross(e2);
    const double det = e1.dot(p);
    if (det == 0.0) return kNoHit;
    const Vec3 s = origin - tri.a;
    const double u = s.dot(p) / det;
    if (u < 0.0 || u > 1.0) return kNoHit;
    const Vec3 q = s.cross(e1);
    const double v = dir.dot(q) / det;
    if (v < 0.0 || u + v > 1.0) return kNoHit;
    const double t = e2.dot(q) / det;
    return t > 0.0 ? t : kNoHit;
}

}  // namespace render
