// The self-filter's face-based ray entry (self_filter/mesh_solid.hpp
// grown_faces_entry over robot/mesh_faces.hpp) against the brute force it
// replaces: the first hit, over every triangle of the mesh, of that
// triangle grown by the radius (closed_form_entry).  For closed meshes,
// convex and not, and for hulls (geometry/convex_hull.hpp): the hull
// holds every point and is closed and oriented.
#include "geometry/convex_hull.hpp"
#include "robot/mesh_faces.hpp"
#include "self_filter/mesh_solid.hpp"
#include "self_filter/ray_entry.hpp"
#include "self_filter/solid_geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace {

using octoprox::Vec3;
using Triangles = std::vector<std::array<uint32_t, 3>>;

// An L-shaped prism (not convex: one concave edge along z), 8 cm tall.
void l_prism(std::vector<Vec3> &v, Triangles &t) {
    const double xy[6][2] = {{0, 0}, {0.2, 0}, {0.2, 0.05}, {0.05, 0.05}, {0.05, 0.2}, {0, 0.2}};
    v.clear(), t.clear();
    for (const double z : {0.0, 0.08})
        for (const auto &p : xy) v.push_back(Vec3(p[0], p[1], z));
    // Bottom (facing -z) and top (facing +z) fans from corner 0, then sides.
    for (uint32_t k = 1; k + 1 < 6; ++k) t.push_back({0, k + 1, k}), t.push_back({6, 6 + k, 6 + k + 1});
    for (uint32_t k = 0; k < 6; ++k) {
        const uint32_t a = k, b = (k + 1) % 6;
        t.push_back({a, b, 6 + b}), t.push_back({a, 6 + b, 6 + a});
    }
}

Triangles hull_triangles(const std::vector<Vec3> &points, std::vector<Vec3> &vertices) {
    octoprox::HullMesh hull;
    EXPECT_TRUE(octoprox::convex_hull(points, hull));
    vertices = hull.vertices;
    return hull.triangles;
}

double brute_entry(const std::vector<Vec3> &v, const Triangles &t, double radius, const Vec3 &o, const Vec3 &d) {
    double best = -1.0, limit = 1.0;
    for (const auto &tri : t) {
        octoprox::Convex c;
        c.kind = octoprox::ConvexKind::kTriangle;
        for (int k = 0; k < 3; ++k) c.v[k] = v[tri[k]];
        const double hit = octoprox::closed_form_entry(c, radius, o, d, limit);
        if (hit >= 0.0) best = hit, limit = hit;
    }
    return best;
}

// Rays from points 0.5-1 m away to points near the mesh, at a placed pose.
void expect_same_entries(const std::vector<Vec3> &v, const Triangles &t, double radius, uint64_t seed) {
    const auto faces = octoprox::build_mesh_faces(v, t);
    ASSERT_EQ(faces->faces.size(), t.size());
    octoprox::Convex pose;
    pose.center = Vec3(0.3, -0.2, 0.9);
    pose.axes = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    std::vector<Vec3> placed;
    for (const Vec3 &x : v) placed.push_back(pose.axes * x + pose.center);
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    int hits = 0;
    for (int i = 0; i < 4000; ++i) {
        const Vec3 target = placed[i % placed.size()] + 0.04 * Vec3(normal(rng), normal(rng), normal(rng));
        const Vec3 origin = target + (0.5 + 0.5 * unit(rng)) * Vec3(normal(rng), normal(rng), normal(rng)).normalized();
        const Vec3 dir = (target - origin) * 1.3;
        const double expected = brute_entry(placed, t, radius + octoprox::kEntryTouch, origin, dir);
        if (expected == 0.0) continue;  // the origin lies in the grown solid
        const double got = octoprox::grown_faces_entry(*faces, pose, radius, origin, dir, 1.0);
        hits += expected >= 0.0;
        ASSERT_EQ(got >= 0.0, expected >= 0.0) << "ray " << i;
        if (expected >= 0.0) {
            // Equal up to rounding, which a grazing ray magnifies: within
            // kEntryTouch along the ray.
            ASSERT_NEAR(got, expected, octoprox::kEntryTouch / dir.norm()) << "ray " << i;
        }
    }
    EXPECT_GT(hits, 1000);
}

TEST(FaceEntry, ConcaveClosedMeshEqualsEveryGrownTriangle) {
    std::vector<Vec3> v;
    Triangles t;
    l_prism(v, t);
    const auto faces = octoprox::build_mesh_faces(v, t);
    int untested = 0;
    for (const auto &f : faces->faces)
        for (int k = 0; k < 3; ++k) untested += (f.edges >> k & 1) == 0;
    // 3 * 20 face edges, 30 edges: 30 owned by their first face, one of
    // them (the inner corner's vertical edge) concave.
    EXPECT_EQ(untested, 31);
    for (const double radius : {0.0, 0.005, 0.02, 0.06}) expect_same_entries(v, t, radius, 11);
}

TEST(FaceEntry, HullsOfRandomPointsEqualEveryGrownTriangle) {
    std::mt19937_64 rng(5);
    std::normal_distribution<double> normal;
    for (int set = 0; set < 4; ++set) {
        std::vector<Vec3> points;
        for (int i = 0; i < 300; ++i) points.push_back(Vec3(0.1 * normal(rng), 0.04 * normal(rng), 0.02 * normal(rng)));
        std::vector<Vec3> v;
        const Triangles t = hull_triangles(points, v);
        for (const auto &f : octoprox::build_mesh_faces(v, t)->faces) ASSERT_GT(f.area2, 0.0);
        for (const double radius : {0.0, 0.02}) expect_same_entries(v, t, radius, 20 + set);
    }
}

TEST(ConvexHull, HoldsEveryPointOfACubeWithPointsOnItsFaces) {
    std::vector<Vec3> points;
    for (int x = 0; x <= 4; ++x)
        for (int y = 0; y <= 4; ++y)
            for (int z = 0; z <= 4; ++z) points.push_back(Vec3(x, y, z) * 0.025);
    octoprox::HullMesh hull;
    ASSERT_TRUE(octoprox::convex_hull(points, hull));
    double volume6 = 0.0;
    for (const auto &t : hull.triangles) volume6 += hull.vertices[t[0]].dot(hull.vertices[t[1]].cross(hull.vertices[t[2]]));
    EXPECT_NEAR(volume6 / 6.0, 0.1 * 0.1 * 0.1, 1e-15);
    for (const auto &t : hull.triangles) {
        const Vec3 n = (hull.vertices[t[1]] - hull.vertices[t[0]]).cross(hull.vertices[t[2]] - hull.vertices[t[0]]);
        for (const Vec3 &p : points) EXPECT_LE(n.normalized().dot(p - hull.vertices[t[0]]), 1e-15);
    }
}

TEST(ConvexHull, RefusesFlatSets) {
    std::vector<Vec3> square = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(0, 1, 0), Vec3(0.5, 0.5, 0)};
    octoprox::HullMesh hull;
    EXPECT_FALSE(octoprox::convex_hull(square, hull));
    EXPECT_TRUE(hull.triangles.empty());
}

}  // namespace
