// An independent check of a planned path: every configuration on each
// segment, at most `step` apart in every joint, set on a copy of the
// robot by forward kinematics and checked by the single-configuration
// calls (opx_query_collide with the world, opx_query_self_collide), none
// of the batch or motion code the planner's checkers use.
#pragma once

#include "octoprox_ompl.hpp"

#include <cstdint>
#include <vector>

namespace opx_ompl {

struct DenseCheckResult {
    uint64_t configurations = 0;
    uint64_t colliding = 0;          // configurations touching the map or an object
    uint64_t self_colliding = 0;     // configurations touching themselves
    double first_collision_at = -1;  // waypoint index + fraction of the first, -1: none
};

// `waypoints`: rows of scene.planned_joints.size() values; `unpadded`:
// the copy of the robot without any padding.
DenseCheckResult dense_check(const CheckScene &scene, const std::vector<std::vector<double>> &waypoints, double step,
                             bool unpadded);

// Prints what the robot touches at `values` (the planned joints): the
// links touching the map or an object, the pairs touching each other.
void explain_collisions(const CheckScene &scene, const std::vector<double> &values, const char *label);

}  // namespace opx_ompl
