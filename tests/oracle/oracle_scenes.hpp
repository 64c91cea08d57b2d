// Octrees for the oracle tests, built through the C ABI only, and the
// oracle's copy of their cells.
#pragma once

#include "oracle_check.hpp"
#include "oracle_random.hpp"

#include <memory>
#include <string>
#include <vector>

namespace oracle {

struct Scene {
    opx_octree *tree = nullptr;
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    std::vector<opx_leaf> leaves;
    std::unique_ptr<CellIndex> cells;  // leaves (+ unknown cubes when asked)
    Vec3 low = Vec3::Zero(), high = Vec3::Zero();  // where links are placed
    std::string label;

    Scene() = default;
    Scene(const Scene &) = delete;
    Scene &operator=(const Scene &) = delete;
    ~Scene() { opx_octree_destroy(tree); }
};

// Reads the leaves back, checks them (check_leaves; exits 1 on a failure)
// and indexes them, with the unknown cubes when with_unknown.
void index_scene(Scene &scene, bool with_unknown);

// Inserts world-frame points as one frame seen from `sensor` (a pose in the
// map frame): the points are first moved into the sensor frame.
void insert_frame(opx_octree *tree, const std::vector<Vec3> &world_points, const opx_pose &sensor, int32_t mode);

// A small random map: resolution 0.1..0.25, a few frames of random
// endpoints and ray casts in a 2..4 m cube, so it has occupied, free and
// (free_threshold 0.4 half of the time) uncertain cells at several levels.
std::unique_ptr<Scene> random_small_scene(Rng &rng, bool with_unknown);

// The paper's synthetic scene: the cube [-20, 20]^3 at 0.2 m, random single
// hits until 7,784 occupied leaves.
std::unique_ptr<Scene> synthetic_scene(Rng &rng);

// A request threshold: 0 (the octree's), a random one, or exactly the
// probability of a random leaf (the ">=" edge).
double random_threshold(Rng &rng, const Scene &scene);

// How one scene is queried: `robots` random robots, each at `states` random
// states (link poses in [low, high]), with the given unknown policy and
// random thresholds (or always the octree's when fixed_threshold).
struct Campaign {
    RobotOptions robot;
    int robots = 5, states = 200;
    Vec3 low = Vec3::Zero(), high = Vec3::Zero();
    int32_t unknown_policy = OPX_UNKNOWN_FREE;
    bool fixed_threshold = false;
};
void run_campaign(Rng &rng, const Scene &scene, const Campaign &campaign, opx_query *query, Checker &checker);

}  // namespace oracle
