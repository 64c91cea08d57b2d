#include "oracle_fcl.hpp"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>

namespace oracle {
namespace {

constexpr double kPi = 3.14159265358979323846;
// FCL's two solvers agree to this when both are right.
constexpr double kSolverAgreement = 1e-7;

CurvedStats stats;

fcl::Transform3d transform_of(const Mat3 &axes, const Vec3 &center) {
    fcl::Transform3d transform = fcl::Transform3d::Identity();
    transform.linear() = axes;
    transform.translation() = center;
    return transform;
}

// FCL returns a negative value (-1) for intersecting shapes.
double fcl_distance(const fcl::CollisionGeometryd &shape, const fcl::Transform3d &shape_pose, const Cell &cell,
                    fcl::GJKSolverType solver) {
    const fcl::Boxd cube(2.0 * cell.half, 2.0 * cell.half, 2.0 * cell.half);
    fcl::DistanceRequestd request;
    request.gjk_solver_type = solver;
    request.distance_tolerance = 1e-12;
    fcl::DistanceResultd result;
    return fcl::distance(&shape, shape_pose, &cube, transform_of(Mat3::Identity(), cell.center), request, result);
}

// Exact bounds from prisms, finer until the bracket is narrower than the
// ambiguity band; returns its middle.
double bracketed_distance(const Cylinder &c, const Cell &cell) {
    double low = 0.0, high = 0.0;
    for (int sides : {256, 1024}) {
        high = polytope_cell_distance(cylinder_prism(c, sides, c.radius), cell);
        low = polytope_cell_distance(cylinder_prism(c, sides, c.radius / std::cos(kPi / sides)), cell);
        if (high - low < kCurvedAmbiguity) return 0.5 * (low + high);
    }
    ++stats.unresolved;
    return 0.5 * (low + high);
}

}  // namespace

double cylinder_cell_distance(const Cylinder &cylinder, const Cell &cell) {
    ++stats.measured;
    const fcl::Cylinderd shape(cylinder.radius, cylinder.length);
    const fcl::Transform3d pose = transform_of(cylinder.axes, cylinder.center);
    const double indep = std::max(0.0, fcl_distance(shape, pose, cell, fcl::GST_INDEP));
    const double libccd = std::max(0.0, fcl_distance(shape, pose, cell, fcl::GST_LIBCCD));
    if (std::abs(indep - libccd) > kSolverAgreement) {
        ++stats.disagreements;
        return bracketed_distance(cylinder, cell);
    }
    if (indep > 0.0) return indep;
    // Intersecting: deeply when the two still intersect after both shrank
    // by twice the ambiguity band (FCL's signed distance asserts here).
    constexpr double kShrink = 2.0 * kCurvedAmbiguity;
    if (cylinder.radius <= kShrink || cylinder.length <= 2.0 * kShrink || cell.half <= kShrink) return 0.0;
    const fcl::Cylinderd thinner(cylinder.radius - kShrink, cylinder.length - 2.0 * kShrink);
    const Cell smaller{cell.center, cell.half - kShrink};
    return fcl_distance(thinner, pose, smaller, fcl::GST_INDEP) > 0.0 ? 0.0 : -1.0;
}

CurvedStats curved_stats() { return stats; }

Polytope cylinder_prism(const Cylinder &c, int sides, double rim) {
    Polytope hull;
    for (int end = 0; end < 2; ++end)
        for (int k = 0; k < sides; ++k) {
            const double angle = 2.0 * kPi * k / sides;
            const Vec3 local(rim * std::cos(angle), rim * std::sin(angle), (end ? 0.5 : -0.5) * c.length);
            hull.vertices.push_back(c.center + c.axes * local);
        }
    for (int k = 0; k < sides; ++k) {
        const int next = (k + 1) % sides;
        hull.faces.push_back({k, next, sides + next});
        hull.faces.push_back({k, sides + next, sides + k});
        if (k > 0 && next > 0) {  // the two caps, as fans from vertex 0
            hull.faces.push_back({0, k, next});
            hull.faces.push_back({sides, sides + k, sides + next});
        }
    }
    return hull;
}

double fcl_box_cell_distance(const OrientedBox &box, const Cell &cell, bool libccd) {
    const fcl::Boxd shape(2.0 * box.half.x(), 2.0 * box.half.y(), 2.0 * box.half.z());
    return std::max(0.0, fcl_distance(shape, transform_of(box.axes, box.center), cell,
                                      libccd ? fcl::GST_LIBCCD : fcl::GST_INDEP));
}

}  // namespace oracle
