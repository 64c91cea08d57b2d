#include "self_filter/ray_entry.hpp"

#include <cmath>

namespace octoprox {
namespace {

// The smaller root of a t^2 + 2 b t + c = 0 (a > 0), when real.
bool first_root(double a, double b, double c, double &t) {
    const double discriminant = b * b - a * c;
    if (discriminant < 0.0) return false;
    t = (-b - std::sqrt(discriminant)) / a;
    return true;
}

// Keeps the earliest hit in [0, limit].
struct FirstHit {
    double limit;
    double t = -1.0;
    void offer(double candidate) {
        if (candidate >= 0.0 && candidate <= limit) limit = candidate, t = candidate;
    }
};

void sphere_hit(const Vec3 &center, double radius, const Vec3 &origin, const Vec3 &dir, FirstHit &hit) {
    const Vec3 m = origin - center;
    double t;
    if (first_root(dir.squaredNorm(), m.dot(dir), m.squaredNorm() - radius * radius, t)) hit.offer(t);
}

// The side of the capsule around segment ab: the infinite cylinder's hit,
// kept when it projects inside the segment.
void cylinder_hit(const Vec3 &a, const Vec3 &b, double radius, const Vec3 &origin, const Vec3 &dir, FirstHit &hit) {
    const Vec3 axis = b - a;
    const double length2 = axis.squaredNorm();
    if (length2 == 0.0) return;
    const Vec3 m = origin - a;
    // Components square to the axis, scaled by length2 to stay polynomial.
    const Vec3 d_perp = dir * length2 - axis * axis.dot(dir);
    const Vec3 m_perp = m * length2 - axis * axis.dot(m);
    double t;
    if (!first_root(d_perp.squaredNorm(), m_perp.dot(d_perp),
                    m_perp.squaredNorm() - radius * radius * length2 * length2, t))
        return;
    const double along = (m + t * dir).dot(axis);
    if (along >= 0.0 && along <= length2) hit.offer(t);
}

void capsule_hit(const Vec3 &a, const Vec3 &b, double radius, const Vec3 &origin, const Vec3 &dir, FirstHit &hit) {
    sphere_hit(a, radius, origin, dir, hit);
    sphere_hit(b, radius, origin, dir, hit);
    cylinder_hit(a, b, radius, origin, dir, hit);
}

// The two faces of the grown triangle: its plane moved by +-radius along
// the normal, hit inside the triangle's outline.
void face_hits(const Vec3 v[3], double radius, const Vec3 &origin, const Vec3 &dir, FirstHit &hit) {
    const Vec3 e1 = v[1] - v[0], e2 = v[2] - v[0];
    Vec3 normal = e1.cross(e2);
    const double area2 = normal.norm();
    if (area2 == 0.0) return;
    normal /= area2;
    const double speed = normal.dot(dir);
    if (speed == 0.0) return;
    for (const double side : {radius, -radius}) {
        const double t = (normal.dot(v[0]) + side - normal.dot(origin)) / speed;
        if (!(t >= 0.0 && t <= hit.limit)) continue;
        const Vec3 q = origin + t * dir - side * normal - v[0];
        // Barycentric coordinates of q in the triangle's plane.
        const double u = normal.dot(q.cross(e2)) / area2, w = normal.dot(e1.cross(q)) / area2;
        if (u >= 0.0 && w >= 0.0 && u + w <= 1.0) hit.offer(t);
    }
}

}  // namespace

double face_entry(const MeshFace &face, double radius, const Vec3 &origin, const Vec3 &dir, double t_max) {
    FirstHit hit{t_max};
    // Everything the face tests lies in the ball around its vertices grown
    // by the radius: a ray that passes the ball by, or reaches it only
    // after t_max, meets none of it.
    {
        const Vec3 m = origin - face.centre;
        const double ball = face.reach + radius, a = dir.squaredNorm(), b = m.dot(dir), c = m.squaredNorm() - ball * ball;
        if (c > 0.0) {
            const double discriminant = b * b - a * c;
            if (b >= 0.0 || discriminant < 0.0) return -1.0;
            // The ball's entry -b/a - sqrt(discriminant)/a beyond t_max, without the root.
            const double beyond = -b - t_max * a;
            if (beyond > 0.0 && beyond * beyond > discriminant) return -1.0;
        }
    }
    if (face.area2 > 0.0) {
        const double height = face.normal.dot(origin) - face.offset, speed = face.normal.dot(dir);
        // From outside its grown slab, which holds all this face tests, the
        // ray meets nothing of the face before the slab's near plane: none
        // when it reaches that plane late or never, the plane's point when
        // it lies over the triangle.  From inside the slab the planes are
        // exits, and the ray comes in across an edge's or a vertex's piece.
        if (std::fabs(height) > radius) {
            if (height * speed >= 0.0) return -1.0;
            const double side = height > 0.0 ? radius : -radius;
            const double t = (side - height) / speed;
            if (!(t <= t_max)) return -1.0;
            const Vec3 e1 = face.v[1] - face.v[0], e2 = face.v[2] - face.v[0];
            const Vec3 q = origin + t * dir - side * face.normal - face.v[0];
            const double u = face.normal.dot(q.cross(e2)) / face.area2, w = face.normal.dot(e1.cross(q)) / face.area2;
            if (u >= 0.0 && w >= 0.0 && u + w <= 1.0) return t;
        }
    }
    for (int k = 0; k < 3; ++k) {
        if (face.edges & (1u << k)) cylinder_hit(face.v[k], face.v[(k + 1) % 3], radius, origin, dir, hit);
        if (face.vertices & (1u << k)) sphere_hit(face.v[k], radius, origin, dir, hit);
    }
    return hit.t;
}

double closed_form_entry(const Convex &core, double radius, const Vec3 &origin, const Vec3 &dir, double t_max) {
    FirstHit hit{t_max};
    switch (core.kind) {
    case ConvexKind::kPoint: sphere_hit(core.center, radius, origin, dir, hit); break;
    case ConvexKind::kSegment: capsule_hit(core.v[0], core.v[1], radius, origin, dir, hit); break;
    case ConvexKind::kTriangle:
        face_hits(core.v, radius, origin, dir, hit);
        for (int k = 0; k < 3; ++k) capsule_hit(core.v[k], core.v[(k + 1) % 3], radius, origin, dir, hit);
        break;
    default: break;
    }
    return hit.t;
}

}  // namespace octoprox
