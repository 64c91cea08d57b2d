// Scenes of the fault tests, generated (no data files): a sensor cloud of a
// small room, maps ray-cast from it, a URDF arm with boxes, spheres and
// cylinders plus a link of capsule, convex hull and mesh added by hand, arm
// configurations, and caller boxes.  Everything is deterministic.
#pragma once

#include <octoprox/octoprox.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace fault {

// Stops the program with a message when a setup call fails (setup is never
// under a failing allocator).
void require_ok(opx_status status, const char *what);

// A new query context with `engine`.
opx_query *new_query(int32_t engine);

// A small pseudo-random generator whose sequence is fixed on every platform.
class Lcg {
public:
    explicit Lcg(uint64_t seed) : state_(seed * 6364136223846793005ull + 1442695040888963407ull) {}
    double uniform(double lo, double hi);

private:
    uint64_t state_;
};

// The sensor sits at kSensorPosition (identity orientation) in the map.
extern const double kSensorPosition[3];

// `count` points (x y z floats, packed) in the sensor frame: a floor, a
// wall, a box on the floor and a ball, seen from the sensor.
std::vector<float> room_cloud(size_t count, uint64_t seed);

opx_insert_options sensor_insert_options(int32_t mode);

// Options of the test maps: free_threshold 0.3, so cells missed once or
// twice are uncertain (cost queries see them).
opx_octree_options map_options(double resolution);

// A map ray-cast from room_cloud(points, seed).
opx_octree *room_map(double resolution, size_t points, uint64_t seed);

// The map's .bt or .ot image (opx_octree_save_memory).
std::vector<unsigned char> map_image(const opx_octree *tree, int32_t format);

// The arm: a URDF of six links (boxes, spheres, cylinders; revolute,
// prismatic, continuous and fixed joints).
extern const char kArmUrdf[];
constexpr size_t kArmJoints = 5;

// The arm from kArmUrdf plus a link "gripper" with a capsule, a convex hull
// and a mesh, which arm_pose() keeps at the tool.
opx_linkset *arm_with_gripper();

// Joint positions of configuration i (any i; they wander over the room).
std::vector<double> arm_configuration(size_t i);

// Moves the arm to configuration i, the gripper following the tool.
void arm_pose(opx_linkset *arm, size_t i);

// Every link's pose at configuration i (arm not moved; a clone is posed).
std::vector<opx_pose> arm_link_poses(const opx_linkset *arm, size_t i);

// `count` waypoints from configuration first on: waypoint-major poses.
std::vector<opx_pose> arm_path(const opx_linkset *arm, size_t first, size_t count);

// An arm of spheres alone (three links, two joints), whose batch reads
// the map's obstacle grid, and its base pose: in the room, reaching the
// box on the floor.
opx_linkset *sphere_arm();
constexpr size_t kSphereArmJoints = 2;
constexpr opx_pose kSphereArmBase = {{0.5, 0.1, 0.2}, {0.0, 0.0, 0.0, 1.0}};
// `count` rows of its joints, seeded.
std::vector<double> sphere_arm_rows(size_t count, uint64_t seed);

// `count` caller boxes (min xyz, max xyz) scattered over the room.
std::vector<double> room_boxes(size_t count, uint64_t seed);

}  // namespace fault
