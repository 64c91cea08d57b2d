// The separating-axis test of a triangle and a cell (triangle_box_sat)
// against the exact distance (GJK): "apart" only when the distance is
// above the limit, "intersecting" only when they intersect, on random
// pairs, on triangles moved to the limit or just into the cell, on
// triangles lying in a cell's face plane or with edges along its axes,
// and on triangles without area.  Most random pairs are decided without
// GJK.
#include "geometry/gjk.hpp"
#include "geometry/triangle_box.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using namespace octoprox;

constexpr double kMargin = 1e-9;

double exact_distance(const Vec3 v[3], const Vec3 &center, const Vec3 &half) {
    Convex triangle;
    triangle.kind = ConvexKind::kTriangle;
    for (int k = 0; k < 3; ++k) triangle.v[k] = v[k];
    GjkQuery query;
    query.cell_center = center;
    query.cell_half = half;
    query.shape = &triangle;
    const GjkResult result = gjk_cell_distance(query);
    return result.intersecting ? 0.0 : result.distance;
}

struct Tally {
    int apart = 0, intersecting = 0, undecided = 0;
};

// The answer must hold for the exact distance; returns it for tallies.
TriangleBoxAnswer check(const Vec3 v[3], const Vec3 &center, const Vec3 &half, double limit, const char *what,
                        int i) {
    const TriangleBoxAnswer answer = triangle_box_sat(v, center, half, limit, kMargin);
    const double distance = exact_distance(v, center, half);
    if (answer == TriangleBoxAnswer::kApart) {
        EXPECT_GT(distance, limit) << what << " case " << i << ": called apart at distance " << distance;
    }
    if (answer == TriangleBoxAnswer::kIntersecting) {
        EXPECT_EQ(distance, 0.0) << what << " case " << i << ": called intersecting at distance " << distance;
    }
    return answer;
}

void count(Tally &tally, TriangleBoxAnswer answer) {
    tally.apart += answer == TriangleBoxAnswer::kApart;
    tally.intersecting += answer == TriangleBoxAnswer::kIntersecting;
    tally.undecided += answer == TriangleBoxAnswer::kUndecided;
}

Vec3 random_point(std::mt19937_64 &rng, double spread) {
    std::uniform_real_distribution<double> u(-spread, spread);
    return Vec3(u(rng), u(rng), u(rng));
}

TEST(TriangleBox, RandomPairsAgreeWithTheDistance) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    Tally tally;
    for (int i = 0; i < 40000; ++i) {
        const Vec3 center = random_point(rng, 2.0);
        const Vec3 half = Vec3::Constant(0.005 + 0.05 * unit(rng));
        const Vec3 at = center + random_point(rng, 0.15);
        const double size = unit(rng) < 0.1 ? 1e-4 : 0.08 * unit(rng);
        const Vec3 v[3] = {at + random_point(rng, size), at + random_point(rng, size), at + random_point(rng, size)};
        const double limit = unit(rng) < 0.5 ? kMargin : 0.02 * unit(rng);
        count(tally, check(v, center, half, limit, "random", i));
    }
    EXPECT_GT(tally.apart, 10000);
    EXPECT_GT(tally.intersecting, 1000);
    EXPECT_LT(tally.undecided, 40000 / 20) << "GJK should decide few random pairs";
}

// A triangle slid along a direction until the exact distance crosses the
// limit: at the limit and a hair either side of it.
TEST(TriangleBox, AtTheLimit) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 center = random_point(rng, 1.0), half = Vec3::Constant(0.01);
        const double limit = unit(rng) < 0.5 ? kMargin : 0.01 * unit(rng);
        const Vec3 shape[3] = {random_point(rng, 0.03), random_point(rng, 0.03), random_point(rng, 0.03)};
        const Vec3 direction = random_point(rng, 1.0).normalized();
        double inside = 0.0, outside = 0.5;  // offsets along direction
        auto placed = [&](double offset, Vec3 v[3]) {
            for (int k = 0; k < 3; ++k) v[k] = center + shape[k] + direction * offset;
        };
        Vec3 v[3];
        placed(inside, v);
        if (exact_distance(v, center, half) > limit) continue;
        for (int step = 0; step < 60; ++step) {
            const double middle = 0.5 * (inside + outside);
            placed(middle, v);
            (exact_distance(v, center, half) > limit ? outside : inside) = middle;
        }
        for (double offset : {inside, outside, inside - 1e-9, outside + 1e-9, inside - 1e-6}) {
            placed(offset, v);
            check(v, center, half, limit, "at the limit", i);
        }
    }
}

// Triangles in a cell face's plane, edges along the cell's axes (their
// cross axes vanish), touching a face, an edge or a corner; and triangles
// without area (a segment, a point).
TEST(TriangleBox, FacesAxesAndDegenerateTriangles) {
    const Vec3 center(0.31, -0.17, 0.05), half = Vec3::Constant(0.01);
    const Vec3 c = center;
    const double h = 0.01;
    int i = 0;
    const Vec3 cases[][3] = {
        {c + Vec3(-h, -h, h), c + Vec3(h, -h, h), c + Vec3(-h, h, h)},                  // on the top face
        {c + Vec3(-2 * h, 0, h), c + Vec3(2 * h, 0, h), c + Vec3(0, 2 * h, h)},          // the top plane, across
        {c + Vec3(-2 * h, 0, h + 1e-12), c + Vec3(2 * h, 0, h + 1e-12), c + Vec3(0, 2 * h, h + 1e-12)},
        {c + Vec3(h, h, h), c + Vec3(2 * h, h, h), c + Vec3(h, 2 * h, 2 * h)},           // at a corner
        {c + Vec3(h, 0, 0), c + Vec3(2 * h, 0, 0), c + Vec3(2 * h, h, 0)},               // on a face, edge on x
        {c + Vec3(0.5 * h, 0, 0), c + Vec3(2 * h, 0, 0), c + Vec3(2 * h, 0, 0)},         // a segment into it
        {c + Vec3(3 * h, 0, 0), c + Vec3(4 * h, 0, 0), c + Vec3(5 * h, 0, 0)},           // a segment beside it
        {c, c, c},                                                                       // a point inside
        {c + Vec3(h, h, 2 * h), c + Vec3(h, h, 2 * h), c + Vec3(h, h, 2 * h)},           // a point above
        {c + Vec3(-h, -0.7 * h, -0.9 * h), c + Vec3(0.8 * h, 0.9 * h, 0.6 * h), c + Vec3(0.9 * h, -0.6 * h, 0.7 * h)},
        {c + Vec3(h + 1e-10, -h, -h), c + Vec3(h + 1e-10, h, -h), c + Vec3(h + 1e-10, 0, h)},  // a hair off a face
    };
    for (const auto &v : cases) {
        for (double limit : {kMargin, 1e-3}) check(v, center, half, limit, "special", i);
        ++i;
    }
    EXPECT_EQ(triangle_box_sat(cases[9], center, half, kMargin, kMargin), TriangleBoxAnswer::kIntersecting)
        << "a triangle through the cell";
    EXPECT_EQ(triangle_box_sat(cases[4], center, half, kMargin, kMargin), TriangleBoxAnswer::kUndecided)
        << "an edge along a cell axis is left to GJK";
    EXPECT_EQ(triangle_box_sat(cases[6], center, half, kMargin, kMargin), TriangleBoxAnswer::kApart);
    EXPECT_NE(triangle_box_sat(cases[7], center, half, kMargin, kMargin), TriangleBoxAnswer::kIntersecting)
        << "a triangle without area is left to GJK";
}

}  // namespace
