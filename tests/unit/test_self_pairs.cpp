// Self-collision inside the library, on hand-made pairs whose answers are
// known in closed form: spheres, boxes, capsules, cylinders, a hull and
// meshes at set gaps, the pair rules (disabled pairs, disabled links, one
// link's own shapes), contacts, penetration and distance witnesses, and
// the pair matrix growing with the links.
#include "query/self/self_collider.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace octoprox;

ShapeDef sphere(double radius) {
    ShapeDef d;
    d.kind = ShapeKind::kSphere, d.radius = radius;
    return d;
}

ShapeDef box(const Vec3 &half) {
    ShapeDef d;
    d.kind = ShapeKind::kBox, d.half_size = half;
    return d;
}

ShapeDef capsule(double radius, double half_length) {
    ShapeDef d;
    d.kind = ShapeKind::kCapsule, d.radius = radius, d.half_length = half_length;
    return d;
}

ShapeDef cylinder(double radius, double half_length) {
    ShapeDef d;
    d.kind = ShapeKind::kCylinder, d.radius = radius, d.half_length = half_length;
    return d;
}

// The closed surface of the cube [-h, h]^3 as 12 triangles.
ShapeDef cube_mesh(double h) {
    ShapeDef d;
    d.kind = ShapeKind::kMesh;
    for (int i = 0; i < 8; ++i) d.vertices.push_back(Vec3(i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h));
    d.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return d;
}

ShapeDef cube_hull(double h) {
    ShapeDef d = cube_mesh(h);
    d.kind = ShapeKind::kConvex;
    d.triangles.clear();
    return d;
}

Pose at(const Vec3 &p) {
    Pose pose;
    pose.translation = p;
    return pose;
}

// Two links, one shape each, link 1 at `offset` from link 0.
LinkSet pair_of(ShapeDef a, ShapeDef b, const Vec3 &offset) {
    LinkSet links;
    links.add_shape(links.add_link("a"), std::move(a));
    links.add_shape(links.add_link("b"), std::move(b));
    links.set_poses({at(Vec3::Zero()), at(offset)});
    return links;
}

double self_distance(const LinkSet &links) {
    SelfCollider collider;
    return collider.distance(links, SelfDistanceSettings()).distance;
}

bool self_collides(const LinkSet &links) {
    SelfCollider collider;
    return collider.collides(links);
}

struct GapCase {
    const char *name;
    ShapeDef a, b;
    Vec3 direction;  // unit; link b sits at (reach + gap) along it
    double reach;    // the centre distance at which the two just touch
};

std::vector<GapCase> gap_cases() {
    return {
        {"spheres", sphere(0.1), sphere(0.2), Vec3::UnitX(), 0.3},
        {"boxes", box(Vec3(0.1, 0.2, 0.3)), box(Vec3(0.2, 0.1, 0.1)), Vec3::UnitY(), 0.3},
        {"capsules side by side", capsule(0.05, 0.3), capsule(0.1, 0.2), Vec3::UnitX(), 0.15},
        {"capsules end to end", capsule(0.05, 0.3), capsule(0.1, 0.2), Vec3::UnitZ(), 0.65},
        {"cylinder caps", cylinder(0.1, 0.2), cylinder(0.3, 0.1), Vec3::UnitZ(), 0.3},
        {"cylinder sides", cylinder(0.1, 0.2), cylinder(0.3, 0.1), Vec3::UnitX(), 0.4},
        {"sphere and box", sphere(0.1), box(Vec3(0.2, 0.2, 0.2)), Vec3::UnitZ(), 0.3},
        {"hull and sphere", cube_hull(0.1), sphere(0.05), Vec3::UnitX(), 0.15},
        {"mesh and sphere", cube_mesh(0.1), sphere(0.05), Vec3::UnitY(), 0.15},
        {"mesh and mesh", cube_mesh(0.1), cube_mesh(0.2), Vec3::UnitZ(), 0.3},
        {"mesh and box", cube_mesh(0.1), box(Vec3(0.3, 0.3, 0.05)), Vec3::UnitZ(), 0.15},
    };
}

TEST(SelfPairs, GapsAreMeasuredAndTouchingCollides) {
    for (const GapCase &c : gap_cases()) {
        for (double gap : {0.01, 1e-6, 0.0}) {
            const LinkSet links = pair_of(c.a, c.b, (c.reach + gap) * c.direction);
            EXPECT_NEAR(self_distance(links), gap, 1e-9) << c.name << " gap " << gap;
            EXPECT_EQ(self_collides(links), gap == 0.0) << c.name << " gap " << gap;
        }
        const LinkSet overlapping = pair_of(c.a, c.b, (c.reach - 0.01) * c.direction);
        EXPECT_TRUE(self_collides(overlapping)) << c.name;
        EXPECT_EQ(self_distance(overlapping), 0.0) << c.name;
    }
}

// A padding of exactly the gap closes it (closed sets); 1 cm apart with a
// 1 cm link padding: touching.
TEST(SelfPairs, PaddingClosesTheGap) {
    LinkSet links = pair_of(box(Vec3(0.1, 0.1, 0.1)), box(Vec3(0.1, 0.1, 0.1)), Vec3(0.21, 0, 0));
    EXPECT_FALSE(self_collides(links));
    EXPECT_NEAR(self_distance(links), 0.01, 1e-12);
    links.set_link_padding(1, 0.005);
    EXPECT_NEAR(self_distance(links), 0.005, 1e-12);
    links.set_link_padding(0, 0.005);
    EXPECT_TRUE(self_collides(links));
}

TEST(SelfPairs, DisabledPairsAndLinksAreSkipped) {
    LinkSet links = pair_of(sphere(0.1), sphere(0.1), Vec3(0.1, 0, 0));
    EXPECT_TRUE(self_collides(links));
    links.set_pair_enabled(1, 0, false);
    EXPECT_FALSE(self_collides(links));
    EXPECT_FALSE(links.pairs().enabled(0, 1));
    SelfCollider collider;
    EXPECT_FALSE(collider.distance(links, SelfDistanceSettings()).found);
    links.set_pair_enabled(0, 1, true);
    links.set_link_enabled(0, false);
    EXPECT_FALSE(self_collides(links));
    links.set_link_enabled(0, true);
    EXPECT_TRUE(self_collides(links));
}

// Shapes of one link never collide with each other.
TEST(SelfPairs, OneLinksShapesDoNotCollide) {
    LinkSet links;
    const uint32_t link = links.add_link("one");
    links.add_shape(link, sphere(0.2));
    links.add_shape(link, box(Vec3(0.2, 0.2, 0.2)));
    links.set_poses({at(Vec3::Zero())});
    EXPECT_FALSE(self_collides(links));
    SelfCollider collider;
    EXPECT_FALSE(collider.distance(links, SelfDistanceSettings()).found);
}

TEST(SelfPairs, ContactsAndPenetration) {
    // Spheres of 0.1 and 0.2, centres 0.25 apart along x: 0.05 deep.
    const LinkSet links = pair_of(sphere(0.1), sphere(0.2), Vec3(0.25, 0, 0));
    SelfCollider collider;
    std::vector<SelfContact> contacts;
    SelfCollisionSettings settings;
    settings.penetration = true;
    const SelfCollisionOutcome o = collider.collide(links, settings, contacts);
    ASSERT_TRUE(o.collided);
    ASSERT_EQ(contacts.size(), 1u);
    const SelfContact &c = contacts[0];
    EXPECT_EQ(c.link_a, 0u);
    EXPECT_EQ(c.link_b, 1u);
    EXPECT_NEAR(c.depth, 0.05, 1e-12);
    EXPECT_NEAR((c.normal - Vec3::UnitX()).norm(), 0.0, 1e-12);
    EXPECT_NEAR((c.position - Vec3(0.075, 0, 0)).norm(), 0.0, 1e-12);

    SelfDistanceSettings signed_settings;
    signed_settings.signed_distance = true;
    const SelfDistanceOutcome d = collider.distance(links, signed_settings);
    EXPECT_NEAR(d.distance, -0.05, 1e-12);
    EXPECT_NEAR((d.on_a - Vec3(0.1, 0, 0)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((d.on_b - Vec3(0.05, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(SelfPairs, BoxesOverlapByEpa) {
    const LinkSet links = pair_of(box(Vec3(0.1, 0.1, 0.1)), box(Vec3(0.1, 0.1, 0.1)), Vec3(0.17, 0.02, 0));
    SelfCollider collider;
    SelfDistanceSettings settings;
    settings.signed_distance = true;
    const SelfDistanceOutcome d = collider.distance(links, settings);
    EXPECT_NEAR(d.distance, -0.03, 1e-12);
}

TEST(SelfPairs, DistanceWitnesses) {
    const LinkSet links = pair_of(box(Vec3(0.1, 0.1, 0.1)), sphere(0.05), Vec3(0.3, 0.05, 0.02));
    SelfCollider collider;
    const SelfDistanceOutcome d = collider.distance(links, SelfDistanceSettings());
    ASSERT_TRUE(d.found);
    EXPECT_NEAR(d.distance, 0.15, 1e-12);
    EXPECT_NEAR((d.on_a - Vec3(0.1, 0.05, 0.02)).norm(), 0.0, 1e-12);
    EXPECT_NEAR((d.on_b - Vec3(0.25, 0.05, 0.02)).norm(), 0.0, 1e-12);
    SelfDistanceSettings cut;
    cut.cutoff = 0.1;
    EXPECT_FALSE(collider.distance(links, cut).found);
}

// max_contacts: 0 answers yes/no, N keeps N and marks the rest truncated.
TEST(SelfPairs, ContactLimits) {
    LinkSet links;
    for (int i = 0; i < 4; ++i) links.add_shape(links.add_link("s"), sphere(0.1));
    links.set_poses({at(Vec3(0, 0, 0)), at(Vec3(0.15, 0, 0)), at(Vec3(0.3, 0, 0)), at(Vec3(5, 0, 0))});
    SelfCollider collider;
    std::vector<SelfContact> contacts;
    SelfCollisionSettings settings;
    settings.max_contacts = UINT32_MAX;
    EXPECT_EQ(collider.collide(links, settings, contacts).truncated, false);
    EXPECT_EQ(contacts.size(), 2u);  // 0-1 and 1-2
    settings.max_contacts = 1;
    EXPECT_FALSE(collider.collide(links, settings, contacts).truncated);
    EXPECT_EQ(contacts.size(), 1u);
    settings.max_contacts = 0;
    const SelfCollisionOutcome o = collider.collide(links, settings, contacts);
    EXPECT_TRUE(o.collided);
    EXPECT_TRUE(contacts.empty());
}

TEST(SelfPairs, PairMatrixGrowsWithLinks) {
    LinkSet links;
    for (int i = 0; i < 70; ++i) links.add_link("l");
    links.set_pair_enabled(3, 65, false);
    for (int i = 0; i < 70; ++i) links.add_link("m");
    EXPECT_FALSE(links.pairs().enabled(65, 3));
    EXPECT_TRUE(links.pairs().enabled(3, 66));
    EXPECT_TRUE(links.pairs().enabled(139, 3));
    EXPECT_EQ(links.pairs().disabled_count(), 1u);
    const LinkSet copy(links);
    EXPECT_FALSE(copy.pairs().enabled(3, 65));
}

}  // namespace
