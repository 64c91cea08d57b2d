// hull_vertex_superset (self_filter/hull_vertices.hpp): the points kept
// span the same hull as all of them: in every direction the farthest kept
// point is as far as the farthest point; points strictly inside go.
#include "self_filter/hull_vertices.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using octoprox::Vec3;

double support(const std::vector<Vec3> &points, const Vec3 &d) {
    double best = -1e300;
    for (const Vec3 &p : points) best = std::max(best, p.dot(d));
    return best;
}

void expect_same_hull(const std::vector<Vec3> &all, const std::vector<Vec3> &kept, std::mt19937_64 &rng) {
    std::normal_distribution<double> normal;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 d(normal(rng), normal(rng), normal(rng));
        EXPECT_EQ(support(kept, d), support(all, d));
    }
}

TEST(HullVertices, KeepsTheHullOfASphereAndDropsItsInside) {
    std::mt19937_64 rng(3);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> radius(0.0, 0.9);
    std::vector<Vec3> points;
    for (int i = 0; i < 600; ++i) points.push_back(Vec3(normal(rng), normal(rng), normal(rng)).normalized() * 0.1);
    for (int i = 0; i < 600; ++i) points.push_back(Vec3(normal(rng), normal(rng), normal(rng)).normalized() * 0.1 * radius(rng));
    const std::vector<Vec3> kept = octoprox::hull_vertex_superset(points);
    EXPECT_LT(kept.size(), 700u) << "the inside goes";
    expect_same_hull(points, kept, rng);
}

TEST(HullVertices, KeepsEveryCornerOfFlatAndElongatedSets) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    std::vector<Vec3> finger, plate;
    for (int i = 0; i < 500; ++i) finger.push_back(Vec3(0.1 * unit(rng), 0.01 * unit(rng), 0.005 * unit(rng)));
    for (int i = 0; i < 500; ++i) plate.push_back(Vec3(unit(rng), unit(rng), 0.0));  // all in one plane
    expect_same_hull(finger, octoprox::hull_vertex_superset(finger), rng);
    expect_same_hull(plate, octoprox::hull_vertex_superset(plate), rng);
}

TEST(HullVertices, SmallSetsComeBackWhole) {
    const std::vector<Vec3> few = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0.2, 0.2, 0.0)};
    EXPECT_EQ(octoprox::hull_vertex_superset(few).size(), few.size());
}

}  // namespace
