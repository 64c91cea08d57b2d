// The lower bounds the distance searches prune with (shape_lower_bound):
// never above the exact shape-cell distance, for random boxes, cylinders
// and capsules, padded, at random poses against random cells; and for
// cylinders and capsules tight beside the round side, where the gap of
// their oriented box is not (a cell off the side at 45 degrees between
// the box's faces).  The collision descents' test (shape_may_touch) never
// says "apart" of a cell the shape touches, meshes included, down to
// cells a picometre inside the touch limit.
#include "narrowphase/narrow_phase.hpp"
#include "narrowphase/shape_distance.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace {

using namespace octoprox;

Pose random_pose(std::mt19937_64 &rng) {
    std::normal_distribution<double> normal;
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    q.normalize();
    Pose pose;
    pose.rotation = q.toRotationMatrix();
    pose.translation = Vec3(normal(rng), normal(rng), normal(rng)) * 0.5;
    return pose;
}

ShapeDef random_def(std::mt19937_64 &rng, ShapeKind kind) {
    std::uniform_real_distribution<double> size(0.05, 1.0);
    ShapeDef def;
    def.kind = kind;
    def.radius = size(rng);
    def.half_length = size(rng);
    def.half_size = Vec3(size(rng), size(rng), size(rng));
    return def;
}

// A random triangle soup, off the shape frame's origin.
ShapeDef random_mesh(std::mt19937_64 &rng) {
    std::uniform_real_distribution<double> coordinate(-0.3, 0.3);
    const Vec3 offset(coordinate(rng), coordinate(rng), coordinate(rng));
    return unit::random_mesh(rng, 12, 8, offset);
}

double exact_distance(const PlacedShape &shape, const Aabb &cell) {
    ShapeCellDistance d;
    uint64_t tests = 0;
    const bool found = shape_cell_distance(shape, cell.center(), cell.half_extent(),
                                           std::numeric_limits<double>::infinity(), d, tests);
    EXPECT_TRUE(found);
    return d.distance;
}

double search_bound(const PlacedShape &shape, const Aabb &cell) {
    return std::max(std::sqrt(shape.box.squared_distance(cell)), shape_lower_bound(shape, cell));
}

TEST(ShapeBounds, NeverAboveTheExactDistance) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int positive = 0;
    for (ShapeKind kind : {ShapeKind::kBox, ShapeKind::kCylinder, ShapeKind::kCapsule}) {
        for (int i = 0; i < 20000; ++i) {
            const ShapeDef def = random_def(rng, kind);
            PlacedShape shape;
            place_shape(def, random_pose(rng), unit(rng) < 0.3 ? 0.1 * unit(rng) : 0.0, true, shape);
            const Vec3 center = Vec3(unit(rng), unit(rng), unit(rng)) * 5.0 - Vec3::Constant(2.5);
            const Vec3 half = Vec3::Constant(0.01 + 0.4 * unit(rng));
            const Aabb cell = Aabb::from_center(center, half);
            const double exact = exact_distance(shape, cell);
            const double bound = search_bound(shape, cell);
            ASSERT_LE(bound, exact * (1.0 + 1e-6) + 1e-9)
                << "kind " << int(kind) << " case " << i << ": the bound exceeds the distance";
            positive += bound > 0.0;
        }
    }
    EXPECT_GT(positive, 20000) << "most cells should be apart from the shape";
}

// A small cell beside the round side, off the oriented box's faces (at 45
// degrees between two of them): there the bound must be the distance, up
// to the cell's size, where the oriented box's gap is about 0.3 of the
// radius short of it.
TEST(ShapeBounds, TightBesideTheRoundSide) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (ShapeKind kind : {ShapeKind::kCylinder, ShapeKind::kCapsule}) {
        for (int i = 0; i < 200; ++i) {
            const ShapeDef def = random_def(rng, kind);
            const Pose pose = random_pose(rng);
            PlacedShape shape;
            place_shape(def, pose, 0.0, true, shape);
            const double gap = 0.05 + 0.5 * unit(rng);
            const Vec3 out = (pose.rotation.col(0) + pose.rotation.col(1)).normalized();
            const Vec3 point = pose.translation + pose.rotation.col(2) * (def.half_length * (2 * unit(rng) - 1) * 0.9) +
                               out * (def.radius + gap);
            const Aabb cell = Aabb::from_center(point, Vec3::Constant(1e-4));
            const double exact = exact_distance(shape, cell);
            EXPECT_NEAR(exact, gap, 2e-4) << "kind " << int(kind) << " case " << i;
            EXPECT_GE(shape_lower_bound(shape, cell), exact - 4e-4) << "kind " << int(kind) << " case " << i;
        }
    }
}

// Random cells around each shape, and for each a cell moved towards the
// shape until it touches (the exact test's own answer): shape_may_touch
// must let every touching cell through.
TEST(ShapeBounds, MayTouchNeverMissesATouchingCell) {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int touching = 0, pruned = 0;
    for (ShapeKind kind : {ShapeKind::kBox, ShapeKind::kCylinder, ShapeKind::kCapsule, ShapeKind::kMesh}) {
        for (int i = 0; i < 4000; ++i) {
            const ShapeDef def = kind == ShapeKind::kMesh ? random_mesh(rng) : random_def(rng, kind);
            PlacedShape shape;
            place_shape(def, random_pose(rng), unit(rng) < 0.3 ? 0.05 * unit(rng) : 0.0, true, shape);
            const Vec3 half = Vec3::Constant(0.005 + 0.2 * unit(rng));
            Vec3 center = shape.box.center() + (Vec3(unit(rng), unit(rng), unit(rng)) - Vec3::Constant(0.5)) * 3.0;
            uint64_t tests = 0;
            // Halve the way to the shape's centre until the cell touches,
            // then step back out while it still does: a cell at the limit.
            Vec3 out = center;
            for (int step = 0; step < 60 && !shape_touches_cell(shape, center, half, tests); ++step) {
                out = center;
                center = 0.5 * (center + shape.box.center());
            }
            if (!shape_touches_cell(shape, center, half, tests)) continue;
            for (int step = 0; step < 50; ++step) {
                const Vec3 middle = 0.5 * (center + out);
                (shape_touches_cell(shape, middle, half, tests) ? center : out) = middle;
            }
            ++touching;
            // A picometre inside the limit: at the limit itself rounding
            // (1e-16 m) decides either way.
            ASSERT_TRUE(shape_may_touch(shape, Aabb::from_center(center, half + Vec3::Constant(1e-12))))
                << "kind " << int(kind) << " case " << i << ": a touching cell was pruned";
            pruned += !shape_may_touch(shape, Aabb::from_center(out + (out - center) * 1e3, half));
        }
    }
    EXPECT_GT(touching, 15000);
    EXPECT_GT(pruned, 0) << "cells apart from the shape should be pruned sometimes";
}

}  // namespace
