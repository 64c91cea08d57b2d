// The generated arms of opx-bench-batch: a 7-joint arm of the size of a
// collaborative arm (0.9 m reach) built of primitives (cylinders, spheres,
// boxes), and the same kinematics approximated by 50 spheres, the robot
// model sphere-based planners use.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace batch_bench {

constexpr int kArmJoints = 7;
constexpr int kArmSpheres = 50;

// URDF text of the primitive arm and of the sphere arm.
std::string primitive_arm_urdf();
std::string sphere_arm_urdf();

// Link index pairs that touch at every configuration (each link and the
// next one, which share a joint): what an SRDF disables.
std::vector<std::pair<uint32_t, uint32_t>> adjacent_arm_links();

}  // namespace batch_bench
