// A robot of spheres checked from the map's obstacle grid (query/batch/
// sphere_robot.hpp): its answer is the one of its spheres asked one by one
// of the descent, with no grid, for links placed all around a small map
// (where the grid's clearance outside its box is exact to the cell, so a
// link's bounding sphere decides often) and around a map of clustered
// cells; with padding, a disabled link and point extents.  A robot with a
// box among its spheres is not bound.
#include "query/batch/sphere_robot.hpp"

#include "octree/obstacle_grid.hpp"
#include "unit_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace {

using octoprox::LinkSet;
using octoprox::Pose;
using octoprox::SensorOctree;
using octoprox::ShapeDef;
using octoprox::ShapeKind;
using octoprox::SphereRobot;
using octoprox::Vec3;

constexpr double kRes = 0.02;

// Occupied cells: `clusters` clumps of `per_cluster` points within 6 cm
// of a centre in [-spread, spread]^3, inserted as endpoints.
std::unique_ptr<SensorOctree> clustered_map(uint64_t seed, int clusters, int per_cluster, double spread) {
    auto tree = unit::empty_octree(kRes);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<double> xyz;
    for (int c = 0; c < clusters; ++c) {
        const Vec3 centre(spread * u(rng), spread * u(rng), spread * u(rng));
        for (int i = 0; i < per_cluster; ++i) {
            const Vec3 p = centre + 0.06 * Vec3(u(rng), u(rng), u(rng));
            xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
        }
    }
    octoprox::InsertSettings settings;
    settings.raycast = false;
    unit::insert_xyz(*tree, xyz, settings);
    return tree;
}

// Three links of four spheres each along their z (radii 2-6 cm), with
// padding, more of it on link 1, and link 2 disabled when asked.
LinkSet sphere_links(bool disable_one) {
    LinkSet links;
    for (int l = 0; l < 3; ++l) {
        const uint32_t link = links.add_link("link" + std::to_string(l));
        for (int s = 0; s < 4; ++s) {
            ShapeDef sphere;
            sphere.kind = ShapeKind::kSphere;
            sphere.radius = 0.02 + 0.01 * s;
            sphere.local.translation = Vec3(0.01 * s, -0.005 * s, 0.07 * s - 0.1);
            links.add_shape(link, std::move(sphere));
        }
    }
    links.set_padding(0.004);
    links.set_link_padding(1, 0.01);
    if (disable_one) links.set_link_enabled(2, false);
    return links;
}

Pose random_pose(std::mt19937_64 &rng, double spread) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Pose pose;
    pose.translation = spread * Vec3(u(rng), u(rng), u(rng));
    pose.rotation = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
    return pose;
}

// The answer sphere by sphere, each from the descent.
bool each_sphere_collides(const SensorOctree &tree, const LinkSet &links, const octoprox::SphereSettings &settings) {
    for (const octoprox::PlacedShape &placed : links.placed())
        if (links.link(placed.link).enabled &&
            octoprox::sphere_collides(tree, nullptr, placed.core.center, placed.inflation, settings))
            return true;
    return false;
}

// Random poses of the links; returns how many collide (both answers alike).
size_t expect_descent_answers(const SensorOctree &tree, LinkSet &links, const octoprox::SphereSettings &settings,
                              double spread, uint64_t seed, int trials) {
    SphereRobot robot;
    EXPECT_TRUE(robot.bind(links));
    const auto grid = octoprox::ObstacleGrid::build(tree.view(), settings.threshold_log_odds, size_t(1) << 30);
    std::mt19937_64 rng(seed);
    size_t collided = 0;
    for (int t = 0; t < trials; ++t) {
        std::vector<Pose> poses;
        for (size_t l = 0; l < links.link_count(); ++l) poses.push_back(random_pose(rng, spread));
        links.set_poses(poses);
        const bool expected = each_sphere_collides(tree, links, settings);
        EXPECT_EQ(robot.collides(tree, grid.get(), poses, settings), expected) << "trial " << t;
        EXPECT_EQ(robot.collides(tree, nullptr, poses, settings), expected) << "trial " << t;
        collided += expected;
    }
    return collided;
}

octoprox::SphereSettings settings_of(const SensorOctree &tree, bool point_extents) {
    octoprox::SphereSettings settings;
    settings.threshold_log_odds = tree.view().bounds_threshold();
    settings.point_extents = point_extents;
    return settings;
}

TEST(SphereRobot, SmallMapEveryPoseAround) {
    const auto tree = clustered_map(3, 1, 12, 0.0);
    LinkSet links = sphere_links(false);
    const size_t collided = expect_descent_answers(*tree, links, settings_of(*tree, false), 0.3, 5, 20000);
    EXPECT_GT(collided, 1000u);
    EXPECT_LT(collided, 19000u);
}

TEST(SphereRobot, ClusteredMapDisabledLinkPointExtents) {
    const auto tree = clustered_map(7, 40, 25, 0.8);
    LinkSet links = sphere_links(true);
    for (const bool point_extents : {false, true}) {
        const size_t collided = expect_descent_answers(*tree, links, settings_of(*tree, point_extents), 0.9, 9, 8000);
        EXPECT_GT(collided, 400u);
        EXPECT_LT(collided, 7600u);
    }
}

TEST(SphereRobot, BindsSpheresAlone) {
    LinkSet links = sphere_links(false);
    ShapeDef box;
    box.kind = ShapeKind::kBox;
    box.half_size = Vec3(0.01, 0.01, 0.01);
    links.add_shape(1, std::move(box));
    SphereRobot robot;
    EXPECT_FALSE(robot.bind(links));
    EXPECT_FALSE(robot.bound());
}

}  // namespace
