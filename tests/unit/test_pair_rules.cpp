// The rules both engines share, on hand-made pairs: boxes' volume and
// intersection, the contact sink's keeping and settling, the distance leaf
// test (signed and not) and the nearest-pair keeper, the cost rule for
// uncertain cells and unknown cubes, and what a query context answers for
// each engine.
#include "base/error.hpp"
#include "query/contact_sink.hpp"
#include "query/context.hpp"
#include "query/nearest_pair.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using namespace octoprox;

// One link with a sphere of radius `radius` centred at `center`.
LinkSet sphere_at(const Vec3 &center, double radius) {
    LinkSet links;
    ShapeDef sphere;
    sphere.kind = ShapeKind::kSphere, sphere.radius = radius;
    links.add_shape(links.add_link("ball"), sphere);
    Pose pose;
    pose.translation = center;
    links.set_poses({pose});
    return links;
}

// A unit cube with its low corner at `lo`.
Aabb unit_cube(const Vec3 &lo) { return Aabb{lo, lo + Vec3::Ones()}; }

CellSummary some_cell() {
    CellSummary cell;
    cell.size = 1.0, cell.cell_class = kOccupied, cell.probability = 0.9;
    return cell;
}

TEST(BoxVolume, FacesOnlyShareNoVolume) {
    const Aabb a = unit_cube(Vec3::Zero());
    EXPECT_TRUE(a.has_volume());
    EXPECT_FALSE(a.intersection(unit_cube(Vec3(1, 0, 0))).has_volume());   // a shared face
    EXPECT_FALSE(a.intersection(unit_cube(Vec3(3, 0, 0))).has_volume());   // apart
    const Aabb overlap = a.intersection(unit_cube(Vec3(0.5, 0.25, 0)));
    EXPECT_TRUE(overlap.has_volume());
    EXPECT_EQ(overlap.lo, Vec3(0.5, 0.25, 0));
    EXPECT_EQ(overlap.hi, Vec3(1, 1, 1));
    EXPECT_FALSE(Aabb().has_volume());
}

// Two cells the sphere touches and one it does not.
struct SinkScene {
    LinkSet links = sphere_at(Vec3(0, 0, 0), 0.6);
    Aabb touched[2] = {unit_cube(Vec3(0.5, -0.5, -0.5)), unit_cube(Vec3(-1.5, -0.5, -0.5))};
    Aabb far = unit_cube(Vec3(5, 5, 5));
    std::vector<Contact> contacts{Contact()};  // cleared by the sink
    CollisionOutcome outcome;

    bool offer(ContactSink &sink, const Aabb &cell) {
        return sink.offer(links.placed()[0], cell, [] { return some_cell(); });
    }
};

TEST(ContactSink, KeepsUpToMaxContactsThenTruncates) {
    SinkScene scene;
    CollisionSettings settings;
    settings.max_contacts = 1;
    ContactSink sink(settings, scene.contacts, scene.outcome);
    EXPECT_TRUE(scene.contacts.empty());
    EXPECT_FALSE(scene.offer(sink, scene.far));
    EXPECT_FALSE(scene.outcome.collided);
    EXPECT_TRUE(scene.offer(sink, scene.touched[0]));  // one is all a query of one wants
    EXPECT_TRUE(scene.outcome.collided);
    EXPECT_FALSE(scene.outcome.truncated);
    ASSERT_EQ(scene.contacts.size(), 1u);
    EXPECT_EQ(scene.contacts[0].cell_class, kOccupied);
    EXPECT_EQ(scene.contacts[0].probability, 0.9);
    const uint64_t tests = scene.outcome.narrow_tests;
    EXPECT_TRUE(scene.offer(sink, scene.touched[1]));  // settled: no further test
    EXPECT_EQ(scene.outcome.narrow_tests, tests);
}

TEST(ContactSink, ManyContactsSettleWhenOneMoreIsFound) {
    SinkScene scene;
    CollisionSettings settings;
    settings.max_contacts = 2;
    ContactSink sink(settings, scene.contacts, scene.outcome);
    EXPECT_FALSE(scene.offer(sink, scene.touched[0]));
    EXPECT_FALSE(scene.offer(sink, scene.touched[1]));
    EXPECT_FALSE(scene.outcome.truncated);
    EXPECT_TRUE(scene.offer(sink, scene.touched[0]));
    EXPECT_TRUE(scene.outcome.truncated);
    EXPECT_EQ(scene.contacts.size(), 2u);
}

TEST(ContactSink, YesNoQueriesKeepNoneAndAreNotTruncated) {
    SinkScene scene;
    CollisionSettings settings;
    settings.max_contacts = 0;
    settings.penetration = true;
    ContactSink sink(settings, scene.contacts, scene.outcome);
    EXPECT_TRUE(scene.offer(sink, scene.touched[0]));
    EXPECT_TRUE(scene.outcome.collided);
    EXPECT_FALSE(scene.outcome.truncated);
    EXPECT_TRUE(scene.contacts.empty());
}

TEST(ContactSink, PenetrationIsTheShapesDepthIntoTheCell) {
    SinkScene scene;
    CollisionSettings settings;
    settings.penetration = true;
    ContactSink sink(settings, scene.contacts, scene.outcome);
    scene.offer(sink, scene.touched[0]);  // the sphere reaches 0.1 into the cell's face x = 0.5
    ASSERT_EQ(scene.contacts.size(), 1u);
    EXPECT_NEAR(scene.contacts[0].depth, 0.1, 1e-9);
    EXPECT_NEAR(std::abs(scene.contacts[0].normal[0]), 1.0, 1e-9);
}

TEST(NearerPair, UnsignedKeepsOnlyPairsBelowTheBound) {
    const LinkSet links = sphere_at(Vec3(0, 0, 0), 0.5);
    const Aabb cell = unit_cube(Vec3(1.5, -0.5, -0.5));  // 1.0 from the sphere
    ShapeCellDistance d;
    uint64_t tests = 0;
    ASSERT_TRUE(nearer_pair(links.placed()[0], cell, 2.0, false, d, tests));
    EXPECT_NEAR(d.distance, 1.0, 1e-9);
    EXPECT_FALSE(nearer_pair(links.placed()[0], cell, 1.0, false, d, tests));
    EXPECT_FALSE(nearer_pair(links.placed()[0], cell, 0.5, false, d, tests));
}

TEST(NearerPair, SignedMeasuresATouchingPairByItsPenetration) {
    const LinkSet links = sphere_at(Vec3(0, 0, 0), 0.6);
    const Aabb cell = unit_cube(Vec3(0.5, -0.5, -0.5));  // 0.1 deep
    ShapeCellDistance d;
    uint64_t tests = 0;
    ASSERT_TRUE(nearer_pair(links.placed()[0], cell, 1.0, true, d, tests));
    EXPECT_NEAR(d.distance, -0.1, 1e-9);
    // In contact, the bound is the deepest so far: only a deeper pair counts.
    EXPECT_TRUE(nearer_pair(links.placed()[0], cell, -0.05, true, d, tests));
    EXPECT_FALSE(nearer_pair(links.placed()[0], cell, -0.2, true, d, tests));
    // Unsigned, a touching pair is at distance 0.
    ASSERT_TRUE(nearer_pair(links.placed()[0], cell, 1.0, false, d, tests));
    EXPECT_EQ(d.distance, 0.0);
}

TEST(NearerPair, InContactAFarCellIsNotNearer) {
    const LinkSet links = sphere_at(Vec3(0, 0, 0), 0.5);
    ShapeCellDistance d;
    uint64_t tests = 0;
    EXPECT_FALSE(nearer_pair(links.placed()[0], unit_cube(Vec3(1.5, 0, 0)), -0.1, true, d, tests));
}

TEST(KeepIfNearer, TakesTheFirstAndThenOnlyNearerPairs) {
    const LinkSet links = sphere_at(Vec3(0, 0, 0), 0.5);
    DistanceOutcome best;
    ShapeCellDistance pair;
    pair.distance = 2.0;
    EXPECT_TRUE(keep_if_nearer(links.placed()[0], pair, best));
    EXPECT_TRUE(best.found);
    pair.distance = 3.0;
    EXPECT_FALSE(keep_if_nearer(links.placed()[0], pair, best));
    pair.distance = 2.0;
    EXPECT_FALSE(keep_if_nearer(links.placed()[0], pair, best));  // a tie keeps the first
    pair.distance = -1.0;
    EXPECT_TRUE(keep_if_nearer(links.placed()[0], pair, best));
    EXPECT_EQ(best.distance, -1.0);
}

TEST(CostOffer, UncertainCellsCountWholeUnknownCubesOnlyInTheRegion) {
    const LinkSet links = sphere_at(Vec3(0, 0, 0), 2.0);
    CollisionSettings settings;
    settings.region = Aabb{Vec3(-1, -1, -1), Vec3(1, 1, 1)};
    settings.unknown_probability = 0.25;
    CostCollector cost;
    uint64_t tests = 0;
    const CellKey a = CellKey{}.child(0), b = CellKey{}.child(1), c = CellKey{}.child(2);
    const Aabb beside_region = unit_cube(Vec3(1, 0, 0));  // shares the region's face x = 1
    cost.offer(links.placed()[0], a, true, 0.0f, beside_region, settings, tests);   // no volume: nothing
    cost.offer(links.placed()[0], b, false, 0.0f, beside_region, settings, tests);  // uncertain: whole
    cost.offer(links.placed()[0], c, true, 0.0f, unit_cube(Vec3(0.5, 0, 0)), settings, tests);  // clipped
    std::vector<CostBox> boxes;
    const std::vector<Aabb> link_boxes{Aabb{Vec3::Constant(-9), Vec3::Constant(9)}};
    const CostSummary summary = cost.finish(link_boxes, 16, boxes);
    ASSERT_EQ(summary.box_count, 2u);
    // Costliest first: the whole uncertain cell (log-odds 0: p 0.5, volume
    // 1), then the unknown cube's half inside the region (p 0.25).
    EXPECT_EQ(boxes[0].cell_class, kUncertain);
    EXPECT_DOUBLE_EQ(boxes[0].cost, 0.5);
    EXPECT_EQ(boxes[1].cell_class, kUnknown);
    EXPECT_EQ(boxes[1].box.lo, Vec3(0.5, 0, 0));
    EXPECT_EQ(boxes[1].box.hi, Vec3(1, 1, 1));
    EXPECT_DOUBLE_EQ(boxes[1].cost, 0.25 * 0.5);
}

TEST(QueryContext, OnlyTheAmortizedEngineTakesCallerBoxes) {
    QueryContext direct(ContextOptions{});
    EXPECT_EQ(direct.engine_kind(), EngineKind::kDirect);
    EXPECT_EQ(direct.stats().builds, 0u);
    EXPECT_THROW(direct.require_box_engine(), ApiError);
    EXPECT_THROW(direct.bind_boxes({unit_cube(Vec3::Zero())}), ApiError);

    ContextOptions options;
    options.engine = EngineKind::kAmortized;
    QueryContext amortized(options);
    EXPECT_NO_THROW(amortized.require_box_engine());
    const LinkSet links = sphere_at(Vec3(0, 0, 0), 0.6);
    EXPECT_THROW(amortized.collide_boxes(links, CollisionSettings()), ApiError);  // none bound yet
    amortized.bind_boxes({unit_cube(Vec3(0.5, -0.5, -0.5)), unit_cube(Vec3(5, 5, 5))});
    const CollisionAnswer hit = amortized.collide_boxes(links, CollisionSettings());
    EXPECT_TRUE(hit.outcome.collided);
    ASSERT_EQ(amortized.contacts().size(), 1u);
    EXPECT_EQ(amortized.contacts()[0].probability, 1.0);
    const DistanceAnswer near = amortized.distance_boxes(links, DistanceSettings(), true);
    ASSERT_TRUE(near.outcome.found);
    EXPECT_EQ(near.outcome.distance, 0.0);
    EXPECT_EQ(near.cell.center, Vec3(1.0, 0.0, 0.0));
    EXPECT_EQ(amortized.link_distances(), std::vector<double>{0.0});
    EXPECT_EQ(amortized.stats().boxes, 2u);
}

}  // namespace
