// The planning problem of the OMPL example: the PR2 of the shared data
// (robots/pr2_description, its full SRDF's disabled pairs) at the map
// origin, head tilted down, left arm tucked; the shared real RGB-D frame
// (rgbd/) ray-cast into a map as if the PR2's head camera had taken it,
// the robot's own points filtered out; a crate and a post as world
// objects.  The right arm plans: its seven joints, in the URDF's limits
// (the continuous roll joints within -pi..pi).
#pragma once

#include "octoprox_ompl.hpp"

#include <array>
#include <string>
#include <vector>

namespace opx_ompl {

constexpr size_t kArmJoints = 7;
// Metres around every link while planning (not in the map's self-filter).
constexpr double kPlanningPadding = 0.01;
extern const char *const kArmJointNames[kArmJoints];

struct Pr2Scene {
    opx_linkset *robot = nullptr;
    opx_octree *map = nullptr;
    opx_world *world = nullptr;
    CheckScene check;
    std::array<double, kArmJoints> lower{}, upper{};
    uint64_t occupied_cells = 0;
    Pr2Scene() = default;
    Pr2Scene(const Pr2Scene &) = delete;
    Pr2Scene &operator=(const Pr2Scene &) = delete;
    ~Pr2Scene();
};

// Status of load_pr2_scene: 0 ok; kMissingData (the message says what is
// missing); 1 on another error (message printed).
constexpr int kMissingData = 77;

// Builds the scene from the shared data folder `data_dir`, the map at
// `resolution` metres.
int load_pr2_scene(const std::string &data_dir, double resolution, Pr2Scene &out);

}  // namespace opx_ompl
