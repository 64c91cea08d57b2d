// Building a world places each shape once: an object of N shapes, added
// shape by shape or read from a scene file, costs N placements (not the
// N^2 / 2 of placing the whole object on every added shape), and moving
// one shape places that shape alone.
#include "world/scene_file.hpp"
#include "world/world.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace octoprox;

constexpr uint32_t kShapes = 2000;

ShapeDef sphere_at(double x) {
    ShapeDef def;
    def.kind = ShapeKind::kSphere;
    def.radius = 0.01;
    def.local.translation = Vec3(x, 0.0, 0.0);
    return def;
}

TEST(WorldPlacements, AddingShapesPlacesEachOnce) {
    World world;
    const uint32_t object = world.add_object("row", Pose());
    for (uint32_t s = 0; s < kShapes; ++s) world.add_shape(object, sphere_at(0.1 * s));
    EXPECT_EQ(world.placements(), kShapes);
    // Every shape sits where its own pose puts it.
    for (uint32_t s = 0; s < kShapes; s += 97) {
        const PlacedShape &placed = world.object(object).placed[s];
        EXPECT_EQ(placed.shape, s);
        EXPECT_NEAR(placed.core.center.x(), 0.1 * s, 1e-12);
    }
}

TEST(WorldPlacements, MovingOneShapePlacesItAlone) {
    World world;
    const uint32_t object = world.add_object("row", Pose());
    for (uint32_t s = 0; s < 10; ++s) world.add_shape(object, sphere_at(s));
    const uint64_t before = world.placements();
    Pose moved;
    moved.translation = Vec3(0.0, 5.0, 0.0);
    world.set_shape_pose(object, 3, moved);
    EXPECT_EQ(world.placements(), before + 1);
    EXPECT_NEAR(world.object(object).placed[3].core.center.y(), 5.0, 1e-12);
    world.set_object_pose(object, moved);  // the object's pose moves all of them
    EXPECT_EQ(world.placements(), before + 1 + 10);
}

TEST(WorldPlacements, ASceneFileOfOneBigObjectPlacesEachShapeOnce) {
    std::string text = "world:\n  collision_objects:\n    - id: many\n      primitives:\n";
    std::string poses = "      primitive_poses:\n";
    for (uint32_t s = 0; s < kShapes; ++s) {
        text += "        - {type: 2, dimensions: [0.01]}\n";
        poses += "        - {position: {x: " + std::to_string(0.1 * s) + "}}\n";
    }
    World world;
    read_scene(text + poses, SceneFormat::kYaml, "many.yaml", world);
    ASSERT_EQ(world.object_count(), 1u);
    EXPECT_EQ(world.object(0).shapes.size(), kShapes);
    EXPECT_EQ(world.placements(), kShapes);
}

}  // namespace
