#include "oracle_self_fcl.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/capsule.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace oracle {
namespace {

constexpr double kSolverAgreement = 1e-7;

struct Placed {
    std::shared_ptr<fcl::CollisionGeometryd> shape;
    fcl::Transform3d pose = fcl::Transform3d::Identity();
};

fcl::Transform3d transform_of(const Mat3 &axes, const Vec3 &center) {
    fcl::Transform3d t = fcl::Transform3d::Identity();
    t.linear() = axes, t.translation() = center;
    return t;
}

// A frame whose z axis runs along `direction` (unit).
Mat3 frame_along(const Vec3 &direction) {
    const Vec3 helper = std::abs(direction.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
    const Vec3 x = helper.cross(direction).normalized();
    Mat3 axes;
    axes.col(0) = x, axes.col(1) = direction.cross(x), axes.col(2) = direction;
    return axes;
}

Placed convex_of(const std::vector<Vec3> &vertices, const std::vector<std::array<int, 3>> &faces) {
    auto points = std::make_shared<std::vector<fcl::Vector3d>>(vertices.begin(), vertices.end());
    auto indices = std::make_shared<std::vector<int>>();
    for (const auto &f : faces) indices->insert(indices->end(), {3, f[0], f[1], f[2]});
    return {std::make_shared<fcl::Convexd>(points, static_cast<int>(faces.size()), indices)};
}

// FCL's form of a piece other than a point (points have a closed form).
Placed fcl_of(const Piece &p) {
    switch (p.kind) {
    case Piece::kCylinder:
        return {std::make_shared<fcl::Cylinderd>(p.cylinder.radius, p.cylinder.length),
                transform_of(p.cylinder.axes, p.cylinder.center)};
    case Piece::kBox:
        return {std::make_shared<fcl::Boxd>(2.0 * p.box.half.x(), 2.0 * p.box.half.y(), 2.0 * p.box.half.z()),
                transform_of(p.box.axes, p.box.center)};
    case Piece::kSegment: {
        const Segment &s = p.edges[0];
        const double length = (s.b - s.a).norm();
        return {std::make_shared<fcl::Capsuled>(0.0, length),
                transform_of(frame_along((s.b - s.a) / length), 0.5 * (s.a + s.b))};
    }
    case Piece::kTriangle: return convex_of(p.vertices, {{0, 1, 2}});
    default: return convex_of(p.hull.vertices, p.hull.faces);
    }
}

// Intersecting: FCL answers a negative number, taken as 0.
double fcl_distance(const Placed &a, const Placed &b, fcl::GJKSolverType solver) {
    fcl::DistanceRequestd request;
    request.gjk_solver_type = solver;
    request.distance_tolerance = 1e-12;
    fcl::DistanceResultd result;
    return std::max(0.0, fcl::distance(a.shape.get(), a.pose, b.shape.get(), b.pose, request, result));
}

}  // namespace

bool fcl_cylinder_distance(const Piece &cylinder, const Piece &other, double &out) {
    if (other.kind == Piece::kPoint) {
        out = point_cylinder_distance(other.vertices[0], cylinder.cylinder);
        return true;
    }
    if (other.kind == Piece::kSegment && (other.edges[0].b - other.edges[0].a).norm() == 0.0) {
        out = point_cylinder_distance(other.edges[0].a, cylinder.cylinder);
        return true;
    }
    const Placed a = fcl_of(cylinder), b = fcl_of(other);
    const double indep = fcl_distance(a, b, fcl::GST_INDEP);
    const double libccd = fcl_distance(a, b, fcl::GST_LIBCCD);
    out = indep;
    return std::abs(indep - libccd) <= kSolverAgreement;
}

}  // namespace oracle
