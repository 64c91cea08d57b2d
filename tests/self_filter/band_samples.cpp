#include "band_samples.hpp"

#include <cmath>

namespace filter_oracle {
namespace {

double uniform(std::mt19937 &rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

Vec3 random_unit(std::mt19937 &rng) {
    std::normal_distribution<double> normal(0.0, 1.0);
    return Vec3(normal(rng), normal(rng), normal(rng)).normalized();
}

// In the shape frame: a point of the box's surface (a random face).
SurfacePoint on_box(const Vec3 &half, std::mt19937 &rng) {
    const int face = std::uniform_int_distribution<int>(0, 5)(rng), axis = face / 2;
    const double sign = face % 2 ? 1.0 : -1.0;
    SurfacePoint s;
    for (int a = 0; a < 3; ++a) s.point[a] = uniform(rng, -half[a], half[a]);
    s.point[axis] = sign * half[axis];
    s.normal = Vec3::Zero();
    s.normal[axis] = sign;
    return s;
}

// On the side (half the time) or a cap of a cylinder or capsule along z;
// `rounded`: the caps are hemispheres at +-half_length.
SurfacePoint on_round(double radius, double half_length, bool rounded, std::mt19937 &rng) {
    SurfacePoint s;
    const double angle = uniform(rng, 0.0, 2.0 * M_PI);
    const Vec3 radial(std::cos(angle), std::sin(angle), 0.0);
    if (uniform(rng, 0.0, 1.0) < 0.5) {
        s.normal = radial;
        s.point = radius * radial + Vec3(0, 0, uniform(rng, -half_length, half_length));
        return s;
    }
    const double sign = uniform(rng, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    if (rounded) {
        s.normal = random_unit(rng);
        s.normal.z() = sign * std::fabs(s.normal.z());
        s.point = Vec3(0, 0, sign * half_length) + radius * s.normal;
        return s;
    }
    s.normal = Vec3(0, 0, sign);
    s.point = std::sqrt(uniform(rng, 0.0, 1.0)) * radius * radial + Vec3(0, 0, sign * half_length);
    return s;
}

// Uniform over the surface: a triangle drawn by its area.
SurfacePoint on_triangles(const std::vector<Triangle> &faces, std::mt19937 &rng) {
    std::vector<double> areas;
    for (const Triangle &f : faces) areas.push_back((f.b - f.a).cross(f.c - f.a).norm());
    const Triangle &t = faces[std::discrete_distribution<size_t>(areas.begin(), areas.end())(rng)];
    double u = uniform(rng, 0.0, 1.0), v = uniform(rng, 0.0, 1.0);
    if (u + v > 1.0) u = 1.0 - u, v = 1.0 - v;
    return SurfacePoint{t.a + u * (t.b - t.a) + v * (t.c - t.a), (t.b - t.a).cross(t.c - t.a).normalized()};
}

}  // namespace

SurfacePoint random_surface_point(const Solid &solid, std::mt19937 &rng) {
    if (solid.surface) return on_triangles(solid.surface->triangles(), rng);  // already in the map frame
    const render::Primitive &p = solid.primitive;
    SurfacePoint s;
    switch (p.kind) {
    case OPX_SHAPE_SPHERE: s.normal = random_unit(rng), s.point = p.radius * s.normal; break;
    case OPX_SHAPE_BOX: s = on_box(p.half_size, rng); break;
    case OPX_SHAPE_CYLINDER: s = on_round(p.radius, p.half_length, false, rng); break;
    default: s = on_round(p.radius, p.half_length, true, rng); break;
    }
    return SurfacePoint{p.map_from_shape * s.point, p.map_from_shape.linear() * s.normal};
}

opx_pose random_pose(std::mt19937 &rng, const Vec3 &centre, double spread) {
    const Eigen::Quaterniond q(Eigen::AngleAxisd(uniform(rng, 0.0, M_PI), random_unit(rng)));
    opx_pose pose = OPX_POSE_IDENTITY;
    for (int a = 0; a < 3; ++a) pose.position[a] = centre[a] + uniform(rng, -spread, spread);
    pose.orientation[0] = q.x(), pose.orientation[1] = q.y(), pose.orientation[2] = q.z(), pose.orientation[3] = q.w();
    return pose;
}

}  // namespace filter_oracle
