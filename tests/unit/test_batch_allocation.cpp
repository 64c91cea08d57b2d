// The batch queries allocate nothing per configuration or per motion: once
// a call has warmed its workers, a call of 400 rows allocates what a call
// of 40 rows does (nothing for configurations on one thread: the workers,
// their posed robots and contexts are kept), with map and self checks and
// distances, beside world objects and without a map, for a 7-joint arm
// with a mesh tool.
#include "alloc_counter.hpp"
#include "unit_scenes.hpp"

#include "query/batch/configuration_batch.hpp"
#include "query/batch/motion_check.hpp"
#include "robot/urdf_model.hpp"
#include "world/world.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>

namespace {

using namespace octoprox;

std::string arm_urdf() {
    std::string xml = "<robot name=\"arm\">";
    for (int k = 0; k <= 7; ++k) {
        xml += "<link name=\"l" + std::to_string(k) + "\"><collision><origin xyz=\"0 0 0.12\"/><geometry>"
               "<cylinder radius=\"0.035\" length=\"0.16\"/></geometry></collision>"
               "<collision><origin xyz=\"0 0 0.22\"/><geometry><box size=\"0.05 0.05 0.02\"/></geometry>"
               "</collision></link>";
        if (k == 0) continue;
        xml += "<joint name=\"j" + std::to_string(k) + "\" type=\"revolute\"><parent link=\"l" + std::to_string(k - 1) +
               "\"/><child link=\"l" + std::to_string(k) + "\"/><origin xyz=\"0 0 0.24\"/><axis xyz=\"0 " +
               (k % 2 ? "0 1" : "1 0") + "\"/><limit lower=\"-3\" upper=\"3\" effort=\"1\" velocity=\"1\"/></joint>";
    }
    return xml + "</robot>";
}

ShapeDef tetra_mesh() {
    ShapeDef def;
    def.kind = ShapeKind::kMesh;
    def.vertices = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 0, 0.1)};
    def.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return def;
}

struct Scene {
    LinkSet links;
    RobotModel robot;
    std::unique_ptr<SensorOctree> tree;
    std::vector<double> rows;
    World world;  // boxes and spheres in the arm's reach

    Scene() {
        UrdfInput input;
        input.xml = arm_urdf();
        input.source = "xml";
        load_urdf(input, links, robot);
        links.add_shape(7, tetra_mesh());
        tree = std::make_unique<SensorOctree>(OctreeParams());
        std::mt19937_64 rng(3);
        std::uniform_real_distribution<double> spread(-1.2, 1.2), height(0.1, 2.0), joint(-3.0, 3.0);
        std::vector<double> xyz;
        for (int i = 0; i < 80; ++i) xyz.insert(xyz.end(), {spread(rng), spread(rng), height(rng)});
        InsertSettings settings;
        settings.raycast = false;
        unit::insert_xyz(*tree, xyz, settings);
        for (int i = 0; i < 400 * 7; ++i) rows.push_back(joint(rng));
        for (int i = 0; i < 24; ++i) {
            Pose at;
            at.translation = Vec3(spread(rng), spread(rng), height(rng));
            ShapeDef shape;
            shape.kind = i % 2 ? ShapeKind::kBox : ShapeKind::kSphere;
            shape.radius = 0.1, shape.half_size = Vec3(0.1, 0.05, 0.08);
            world.add_shape(world.add_object("thing", at), std::move(shape));
        }
    }
    JointRows joint_rows(size_t count) const { return JointRows{reinterpret_cast<const unsigned char *>(rows.data()), count, 7, 56}; }
};

// Allocations of one call of check_configurations over `count` rows.
uint64_t configuration_allocations(Scene &scene, BatchWorkers &workers, const ConfigurationSettings &settings,
                                   size_t count, const Obstacles &obstacles) {
    BasePoses bases;
    bases.poses.emplace_back();
    std::vector<uint8_t> collided(count);
    std::vector<double> distances(count);
    const uint64_t before = unit::allocation_count();
    check_configurations(workers, obstacles, scene.links, scene.robot.joints, scene.joint_rows(count), bases,
                         settings, ConfigurationOutputs{collided.data(), distances.data()});
    return unit::allocation_count() - before;
}

TEST(BatchAllocation, ConfigurationsAllocateNothingOnceWarm) {
    Scene scene;
    BatchWorkers workers{ContextOptions()};
    const Obstacles kinds[3] = {{scene.tree.get(), nullptr}, {scene.tree.get(), &scene.world}, {nullptr, &scene.world}};
    for (int k = 0; k < 12; ++k) {
        ConfigurationSettings settings;
        settings.collision.max_contacts = 0;
        settings.self_collision = (k & 1) != 0;
        settings.distance = (k & 2) != 0;
        const Obstacles &obstacles = kinds[k / 4];
        configuration_allocations(scene, workers, settings, 400, obstacles);  // warms every path
        EXPECT_EQ(configuration_allocations(scene, workers, settings, 40, obstacles), 0u) << "case " << k;
        EXPECT_EQ(configuration_allocations(scene, workers, settings, 400, obstacles), 0u) << "case " << k;
    }
}

uint64_t motion_allocations(Scene &scene, BatchWorkers &workers, size_t count, const Obstacles &obstacles) {
    MotionSettings settings;
    settings.collision.max_contacts = 0;
    settings.resolution = 0.05;
    settings.self_collision = true;
    BasePoses bases;
    bases.poses.emplace_back();
    std::vector<uint8_t> collided(count);
    std::vector<double> fractions(count);
    const JointRows starts = scene.joint_rows(count);
    JointRows goals = starts;
    goals.bytes += 7 * sizeof(double);  // each motion goes to the next row
    const uint64_t before = unit::allocation_count();
    check_motions(workers, obstacles, scene.links, scene.robot.joints, starts, goals, bases, settings,
                  collided.data(), fractions.data());
    return unit::allocation_count() - before;
}

TEST(BatchAllocation, MotionsAllocatePerCallNotPerMotion) {
    Scene scene;
    BatchWorkers workers{ContextOptions()};
    for (const Obstacles &obstacles : {Obstacles{scene.tree.get(), nullptr}, Obstacles{scene.tree.get(), &scene.world}}) {
        motion_allocations(scene, workers, 399, obstacles);
        EXPECT_EQ(motion_allocations(scene, workers, 39, obstacles), motion_allocations(scene, workers, 399, obstacles));
    }
}

}  // namespace
