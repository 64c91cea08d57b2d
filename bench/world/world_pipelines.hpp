// The timed pipelines of opx-bench-world, each over every configuration
// of the robot:
//   octoprox   opx_linkset_set_joint_positions (forward kinematics, timed
//              as the pose update), then opx_query_collide (yes/no) on a
//              direct context with the world set, the octree or NULL
//   batch      opx_query_check_configurations: every configuration in one
//              call, forward kinematics inside, the world set
//   fcl        FclRobot::set_link_poses (the configuration's link poses
//              from OctoProx's FK: placing and refitting FCL's objects,
//              timed as the pose update), then the robot's manager against
//              the objects' manager, stopping at the first contact
// Each runs once untimed (its answers), then in `rounds` rounds, the order
// rotating, so a change of the machine's load hits all alike; the times
// are the median round's.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "world_scene.hpp"

namespace world_bench {

// Milliseconds spent updating poses and querying, over one pass.
struct Split {
    double pose_ms = 0.0, query_ms = 0.0;
};

using Pipeline = std::function<Split(std::vector<uint8_t> &collided)>;

Pipeline opx_pipeline(Robot &robot, const opx_octree *tree, const opx_world *world);
// One opx_query_check_configurations call over every configuration, its
// forward kinematics inside (timed as the query), on `threads` workers.
Pipeline opx_batch_pipeline(Robot &robot, const opx_octree *tree, const opx_world *world, uint32_t threads);
Pipeline fcl_pipeline(Robot &robot, paper_tables::FclManager &objects);

struct Timing {
    double pose_us = 0.0, query_us = 0.0;  // per configuration, the median round's
    double fastest_query_us = 0.0;         // the fastest round's
    std::vector<uint8_t> collided;         // per configuration
};

std::vector<Timing> time_interleaved(size_t configurations, int rounds, const std::vector<Pipeline> &pipelines);

// The signed distance (m) from the robot at configuration `i` to the
// world's objects (negative: the deepest penetration), by OctoProx.
double object_distance(Robot &robot, size_t i, const opx_world *world);

}  // namespace world_bench
