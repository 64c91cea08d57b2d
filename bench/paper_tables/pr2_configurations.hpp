// The PR2 configurations of Table IV.  The robot stands where
// `opx-demo --real` puts it (root link at the map origin, head tilted
// 0.82 rad); both arms reach forward into the sensed scene.  Candidate
// configurations draw each arm joint uniformly around that reaching pose
// (clamped to the URDF limits); OctoProx (direct engine) sorts them into
//   collision set: colliding, with a penetration depth within [min, max]
//                  (the paper: 2.8 cm on average)
//   distance set:  collision-free, distance within [min, max] (paper: 3.4 cm)
// until each set holds the requested number.
// Penetration depth: how far the robot must be lifted (translated along
// +z, the level surface's normal: the head tilt makes the frame's large
// surface level) to clear the map, by bisection on collision queries.
// The library's own depth (EPA, signed_distance = 1) is per shape-cell
// pair: for surface meshes (all of the PR2's arm links) it cannot exceed
// about a cell's size, however deep the arm reaches through the sensed
// surface, so it is reported alongside but not used to choose.
#pragma once

#include <cstdint>
#include <vector>

#include <octoprox/octoprox.h>

namespace paper_tables {

struct Configuration {
    std::vector<double> joints;    // model order (opx_linkset_set_joint_positions)
    std::vector<opx_pose> poses;   // every link's pose after FK, map frame
    double signed_distance = 0.0;  // metres (opx, signed_distance = 1); < 0: minus the deepest EPA depth
    double lift_depth = 0.0;       // metres: the lift that clears a colliding configuration
};

struct ConfigurationSets {
    std::vector<Configuration> collision;
    std::vector<Configuration> distance;
    int drawn = 0;  // candidates drawn
};

// Draws candidates until both sets hold `count` configurations (or a cap
// on the draws is reached: the sets are then smaller, said on stdout), and
// prints how they were chosen and their averages.  The link set is left at
// its starting joint positions.
ConfigurationSets choose_configurations(opx_linkset *robot, const opx_octree *tree, int count);

// `count` configurations drawn as the candidates above are (each arm joint
// uniform around the reaching pose, clamped to the URDF limits) from `seed`,
// with their link poses after FK with the root link at `base` (map frame).
// No map is consulted; the link set is left at its starting joint positions.
std::vector<Configuration> draw_reaching_configurations(opx_linkset *robot, int count, uint64_t seed,
                                                        const opx_pose &base);

// Moves the link set to the configuration's link poses (no FK needed).
void apply_configuration(opx_linkset *robot, const Configuration &configuration);

}  // namespace paper_tables
