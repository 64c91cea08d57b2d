// placed_union, the bounds of a posed mesh: for 1 to 40 random boxes (not
// only multiples of the four lanes) and points at random poses, it holds
// every placed corner and point, and is the tight union to within its
// rounding pad (1e-12 relative); the AVX2 and the portable loops agree bit
// for bit.
#include "base/avx2.hpp"
#include "robot/box_columns.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using namespace octoprox;

Eigen::Matrix3d random_rotation(std::mt19937_64 &rng) {
    std::normal_distribution<double> normal;
    Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
    return q.normalized().toRotationMatrix();
}

// The tight union of the placed corners, by brute force.
Aabb placed_corners(const std::vector<Aabb> &boxes, const Eigen::Matrix3d &rotation, const Vec3 &center) {
    Aabb out;
    for (const Aabb &box : boxes)
        for (int corner = 0; corner < 8; ++corner) {
            const Vec3 p((corner & 1) ? box.hi.x() : box.lo.x(), (corner & 2) ? box.hi.y() : box.lo.y(),
                         (corner & 4) ? box.hi.z() : box.lo.z());
            out.grow(Vec3(rotation * p + center));
        }
    return out;
}

void expect_tight_hull(const Aabb &got, const Aabb &exact, int count) {
    for (int axis = 0; axis < 3; ++axis) {
        EXPECT_LE(got.lo[axis], exact.lo[axis]) << count << " boxes, axis " << axis;
        EXPECT_GE(got.hi[axis], exact.hi[axis]) << count << " boxes, axis " << axis;
        EXPECT_NEAR(got.lo[axis], exact.lo[axis], 1e-9) << count << " boxes, axis " << axis;
        EXPECT_NEAR(got.hi[axis], exact.hi[axis], 1e-9) << count << " boxes, axis " << axis;
    }
}

TEST(BoxColumns, UnionOfPlacedBoxesIsTightAndHoldsEveryCorner) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0), edge(0.0, 0.5);
    std::printf("placed by %s\n", cpu_has_avx2() ? "AVX2 lanes" : "the portable loop");
    for (int count = 1; count <= 40; ++count) {
        std::vector<Aabb> boxes;
        for (int b = 0; b < count; ++b) {
            const Vec3 c(coordinate(rng), coordinate(rng), coordinate(rng));
            boxes.push_back(Aabb::from_center(c, Vec3(edge(rng), edge(rng), edge(rng))));
        }
        const Eigen::Matrix3d rotation = random_rotation(rng);
        const Vec3 center(coordinate(rng), coordinate(rng), coordinate(rng));
        expect_tight_hull(placed_union(box_columns(boxes), rotation, center), placed_corners(boxes, rotation, center),
                          count);
    }
}

TEST(BoxColumns, PointsGiveTheirExactBox) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    for (int count = 1; count <= 21; count += 4) {
        std::vector<Vec3> points;
        std::vector<Aabb> as_boxes;
        for (int i = 0; i < count; ++i) {
            points.emplace_back(coordinate(rng), coordinate(rng), coordinate(rng));
            as_boxes.push_back(Aabb::from_center(points.back(), Vec3::Zero()));
        }
        const Eigen::Matrix3d rotation = random_rotation(rng);
        const Vec3 center(0.3, -0.2, 1.0);
        expect_tight_hull(placed_union(point_columns(points), rotation, center),
                          placed_corners(as_boxes, rotation, center), count);
    }
}

TEST(BoxColumns, BothLoopsGiveTheSameBox) {
    if (!cpu_has_avx2()) GTEST_SKIP() << "no AVX2 here";
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0), edge(0.0, 0.5);
    for (int count = 1; count <= 23; ++count) {
        std::vector<Aabb> boxes;
        for (int b = 0; b < count; ++b)
            boxes.push_back(Aabb::from_center(Vec3(coordinate(rng), coordinate(rng), coordinate(rng)),
                                              Vec3(edge(rng), edge(rng), edge(rng))));
        const Eigen::Matrix3d rotation = random_rotation(rng);
        double r[3][3], s[3][3], t[3] = {0.1, 0.2, 0.3}, lo[2][3], hi[2][3];
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) r[i][j] = rotation(i, j), s[i][j] = std::fabs(rotation(i, j));
            lo[0][i] = lo[1][i] = 1e300, hi[0][i] = hi[1][i] = -1e300;
        }
        const BoxColumns columns = box_columns(boxes);
        placed_union_portable(columns, r, s, t, lo[0], hi[0]);
        placed_union_avx2(columns, r, s, t, lo[1], hi[1]);
        for (int i = 0; i < 3; ++i) EXPECT_TRUE(lo[0][i] == lo[1][i] && hi[0][i] == hi[1][i]) << count;
    }
}

TEST(BoxColumns, NoBoxesGiveAnEmptyBox) {
    EXPECT_TRUE(placed_union(box_columns({}), Eigen::Matrix3d::Identity(), Vec3::Zero()).empty());
}

}  // namespace
