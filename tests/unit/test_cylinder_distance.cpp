// Cylinder-to-cell distances by cylinder_cell_distance: beyond a cap and
// beside the round side answered without GJK on the cylinder, the rest by
// it.  For random cylinders and cells, every answer is exact: its witness
// points lie on the cylinder and in the cell at the distance (so the
// distance is at most the true one) and the plane square to them
// separates the two by the distance (so it is at least the true one, from
// the support functions of both, in closed form).  It is never above GJK's
// on the whole cylinder (an upper bound), a stop_above answer is a true
// lower bound, and each of the three ways is taken many times.
#include "geometry/cylinder_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace octoprox;

Convex random_cylinder(std::mt19937_64 &rng) {
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> size(0.05, 1.5);
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    q.normalize();
    Convex c;
    c.kind = ConvexKind::kCylinder;
    c.center = Vec3(normal(rng), normal(rng), normal(rng));
    c.axes = q.toRotationMatrix();
    // A third of them upright: cells then meet caps and sides face on.
    if (rng() % 3 == 0) c.axes.setIdentity();
    const double radius = size(rng);
    c.half = Vec3(radius, radius, size(rng));
    return c;
}

// On the cylinder's surface or inside it, up to rounding.
void expect_on_cylinder(const Convex &c, const Vec3 &p, int i) {
    const Vec3 local = c.axes.transpose() * (p - c.center);
    const double scale = 1e-12 * (1.0 + c.center.norm() + c.half.norm());
    EXPECT_LE(std::hypot(local.x(), local.y()), c.half.x() + scale) << "case " << i;
    EXPECT_LE(std::abs(local.z()), c.half.z() + scale) << "case " << i;
}

// The gap between the cell and the cylinder along unit direction n (from
// the cylinder to the cell): the cell's lowest point along n minus the
// cylinder's highest.  No point pair is nearer than it.
double separation_along(const Convex &c, const GjkQuery &q, const Vec3 &n) {
    const Vec3 axis = c.axes.col(2);
    const double along = n.dot(axis);
    const double cylinder_top = n.dot(c.center) + c.half.z() * std::abs(along) + c.half.x() * (n - along * axis).norm();
    const double cell_bottom = n.dot(q.cell_center) - n.cwiseAbs().dot(q.cell_half);
    return cell_bottom - cylinder_top;
}

TEST(CylinderDistance, ExactAndNeverAboveGjk) {
    std::mt19937_64 rng(31);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int taken[3] = {0, 0, 0};
    for (int i = 0; i < 30000; ++i) {
        const Convex cylinder = random_cylinder(rng);
        GjkQuery q;
        q.shape = &cylinder;
        q.cell_center = cylinder.center + Vec3(normal(rng), normal(rng), normal(rng)) * 1.5;
        q.cell_half = Vec3::Constant(0.02 + 0.3 * unit(rng));
        if (unit(rng) < 0.3) q.cell_half = Vec3(0.02 + 0.3 * unit(rng), 0.02 + 0.3 * unit(rng), 0.02 + 0.3 * unit(rng));
        const GjkResult reference = gjk_cell_distance(q);
        CylinderPath path;
        const GjkResult r = cylinder_cell_distance(q, &path);
        ++taken[static_cast<int>(path)];
        ASSERT_EQ(r.intersecting, reference.intersecting) << "case " << i;
        EXPECT_LE(r.distance, reference.distance + 1e-12) << "case " << i << ": above GJK's upper bound";
        if (path == CylinderPath::kGjk) {
            EXPECT_EQ(r.distance, reference.distance) << "case " << i;
        }
        if (r.intersecting) continue;
        EXPECT_NEAR((r.on_shape - r.on_cell).norm(), r.distance, 1e-12 * (1.0 + r.distance)) << "case " << i;
        expect_on_cylinder(cylinder, r.on_shape, i);
        const Vec3 outside = ((r.on_cell - q.cell_center).cwiseAbs() - q.cell_half).cwiseMax(0.0);
        EXPECT_LE(outside.norm(), 1e-12) << "case " << i << ": the cell witness is not in the cell";
        if (path != CylinderPath::kGjk) {
            EXPECT_NEAR(separation_along(cylinder, q, (r.on_cell - r.on_shape) / r.distance), r.distance, 1e-12)
                << "case " << i << ": not separated by the distance";
        }

        // The same pair with a bound to stop above: a lower bound above it,
        // or the distance itself.
        GjkQuery bounded = q;
        bounded.stop_above = reference.distance * unit(rng) * 1.5;
        const GjkResult b = cylinder_cell_distance(bounded);
        if (b.distance > bounded.stop_above) {
            EXPECT_LE(b.distance, r.distance + 1e-12) << "case " << i;
        } else {
            EXPECT_NEAR(b.distance, r.distance, 1e-12 * (1.0 + r.distance)) << "case " << i;
        }
    }
    EXPECT_GT(taken[static_cast<int>(CylinderPath::kCap)], 1000);
    EXPECT_GT(taken[static_cast<int>(CylinderPath::kSide)], 1000);
    EXPECT_GT(taken[static_cast<int>(CylinderPath::kGjk)], 1000);
}

// Worked by hand: an upright cylinder (radius 0.5, half length 1) at the
// origin; a cell of half size 0.1 above the top cap, one beside the side.
TEST(CylinderDistance, HandWorkedCapAndSide) {
    Convex c;
    c.kind = ConvexKind::kCylinder;
    c.half = Vec3(0.5, 0.5, 1.0);
    GjkQuery q;
    q.shape = &c;
    q.cell_half = Vec3::Constant(0.1);
    CylinderPath path;
    q.cell_center = Vec3(0.2, -0.1, 1.4);  // bottom face at z = 1.3, above the disk
    GjkResult r = cylinder_cell_distance(q, &path);
    EXPECT_EQ(path, CylinderPath::kCap);
    EXPECT_NEAR(r.distance, 0.3, 1e-15);
    EXPECT_NEAR(r.on_shape.z(), 1.0, 1e-15);
    q.cell_center = Vec3(0.0, 1.1, 0.3);  // near face at y = 1.0, 0.5 from the side
    r = cylinder_cell_distance(q, &path);
    EXPECT_EQ(path, CylinderPath::kSide);
    EXPECT_NEAR(r.distance, 0.5, 1e-15);
    EXPECT_NEAR(r.on_shape.y(), 0.5, 1e-15);
    q.cell_center = Vec3(0.8, 0.8, 1.3);  // off the rim: neither
    r = cylinder_cell_distance(q, &path);
    EXPECT_EQ(path, CylinderPath::kGjk);
    const double rim = std::hypot(0.7 - 0.5 / std::sqrt(2.0), 0.7 - 0.5 / std::sqrt(2.0));
    EXPECT_NEAR(r.distance, std::hypot(rim, 0.2), 1e-9);
}

}  // namespace
