// The world's broad phase and bookkeeping inside the library: a world of
// hundreds of objects answers as the same pairs tested one by one with no
// tree (every robot shape against every object shape), after every kind of
// change (poses, enabled flags, removals, new shapes), and removal keeps
// the placed shapes' object indices in step with the objects.
#include "narrowphase/shape_pair.hpp"
#include "query/world/world_collider.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <tuple>

namespace {

using namespace octoprox;

Pose random_pose(std::mt19937_64 &rng, double extent) {
    std::uniform_real_distribution<double> u(-extent, extent), angle(-M_PI, M_PI);
    Pose pose;
    pose.translation = Vec3(u(rng), u(rng), u(rng));
    pose.rotation = Eigen::AngleAxisd(angle(rng), Vec3(u(rng), u(rng), u(rng) + 1e-3).normalized()).toRotationMatrix();
    return pose;
}

ShapeDef random_shape(std::mt19937_64 &rng) {
    std::uniform_real_distribution<double> size(0.02, 0.3);
    ShapeDef d;
    switch (rng() % 4) {
    case 0: d.kind = ShapeKind::kSphere, d.radius = size(rng); break;
    case 1: d.kind = ShapeKind::kBox, d.half_size = Vec3(size(rng), size(rng), size(rng)); break;
    case 2: d.kind = ShapeKind::kCylinder, d.radius = size(rng), d.half_length = size(rng); break;
    default: d.kind = ShapeKind::kCapsule, d.radius = size(rng), d.half_length = size(rng); break;
    }
    d.local = random_pose(rng, 0.2);
    return d;
}

using Pair = std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>;  // link, shape, object, object shape

// Every touching pair, and the least distance, with no broad phase.
struct Brute {
    std::set<Pair> touching;
    double distance = std::numeric_limits<double>::infinity();
};

Brute brute_force(const World &world, const LinkSet &links) {
    Brute out;
    uint64_t tests = 0;
    for (const PlacedShape &a : links.placed()) {
        if (a.box.empty()) continue;
        for (uint32_t o = 0; o < world.object_count(); ++o) {
            if (!world.object(o).enabled) continue;
            for (const PlacedShape &b : world.object(o).placed) {
                if (shapes_touch(a, b, tests)) out.touching.insert({a.link, a.shape, b.link, b.shape});
                ShapePairDistance d;
                if (shape_pair_distance(a, b, out.distance, d, tests)) out.distance = d.distance;
            }
        }
    }
    return out;
}

// Returns how many pairs touch.
size_t expect_same_answers(const World &world, const LinkSet &links, WorldCollider &collider) {
    const Brute brute = brute_force(world, links);
    std::vector<WorldContact> contacts;
    WorldCollisionSettings all;
    all.max_contacts = UINT32_MAX;
    const WorldCollisionOutcome o = collider.collide(world, links, all, contacts);
    std::set<Pair> found;
    for (const WorldContact &c : contacts) found.insert({c.link, c.shape, c.object, c.object_shape});
    EXPECT_EQ(found, brute.touching);
    EXPECT_EQ(o.collided, !brute.touching.empty());
    const WorldDistance d = collider.distance(world, links, std::numeric_limits<double>::infinity(), false, nullptr);
    EXPECT_EQ(d.found, std::isfinite(brute.distance));
    if (d.found) {
        EXPECT_NEAR(d.distance, brute.distance, 1e-12);
    }
    return brute.touching.size();
}

LinkSet random_robot(std::mt19937_64 &rng) {
    LinkSet links;
    std::vector<Pose> poses;
    for (uint32_t l = 0; l < 6; ++l) {
        links.add_link("link");
        for (int s = 0; s < 2; ++s) links.add_shape(l, random_shape(rng));
        poses.push_back(random_pose(rng, 2.0));
    }
    links.set_poses(poses);
    return links;
}

TEST(WorldIndex, HundredsOfObjectsAnswerAsEveryPairDoes) {
    std::mt19937_64 rng(7);
    World world;
    for (int i = 0; i < 400; ++i) {
        const uint32_t o = world.add_object("object", random_pose(rng, 2.5));
        for (uint64_t s = 0, n = 1 + rng() % 3; s < n; ++s) world.add_shape(o, random_shape(rng));
    }
    WorldCollider collider;
    size_t touching = 0;
    for (int k = 0; k < 10; ++k) {
        const LinkSet links = random_robot(rng);
        touching += expect_same_answers(world, links, collider);
    }
    EXPECT_GT(touching, 10u);  // the robots do meet objects
}

TEST(WorldIndex, EveryChangeReachesTheTree) {
    std::mt19937_64 rng(11);
    World world;
    for (int i = 0; i < 60; ++i) world.add_shape(world.add_object("o", random_pose(rng, 1.5)), random_shape(rng));
    const LinkSet links = random_robot(rng);
    WorldCollider collider;
    expect_same_answers(world, links, collider);
    const uint64_t before = world.generation();
    for (uint32_t o = 0; o < 60; o += 3) world.set_object_pose(o, random_pose(rng, 1.5));
    EXPECT_GT(world.generation(), before);
    expect_same_answers(world, links, collider);
    for (uint32_t o = 1; o < 60; o += 4) world.set_object_enabled(o, false);
    expect_same_answers(world, links, collider);
    for (uint32_t o = 0; o < 10; ++o) world.add_shape(o, random_shape(rng));
    expect_same_answers(world, links, collider);
    world.set_shape_pose(5, 0, random_pose(rng, 0.3));
    expect_same_answers(world, links, collider);
    for (int i = 0; i < 20; ++i) world.remove_object(static_cast<uint32_t>(rng() % world.object_count()));
    expect_same_answers(world, links, collider);
}

TEST(WorldIndex, RemovalRenumbersTheLaterObjects) {
    World world;
    ShapeDef ball;
    ball.kind = ShapeKind::kSphere, ball.radius = 0.1;
    for (int i = 0; i < 5; ++i) world.add_shape(world.add_object("o" + std::to_string(i), Pose()), ball);
    world.remove_object(1);
    ASSERT_EQ(world.object_count(), 4u);
    EXPECT_EQ(world.object(1).name, "o2");
    EXPECT_EQ(world.find_object("o4"), 3);
    EXPECT_EQ(world.find_object("o1"), -1);
    for (uint32_t o = 0; o < world.object_count(); ++o) EXPECT_EQ(world.object(o).placed[0].link, o);
    for (const PlacedShape *p : world.index().shapes) EXPECT_LT(p->link, world.object_count());
}

}  // namespace
