// The cases of the malloc-failure sweep, by subject.
#pragma once

#include "fault_sweep.hpp"

#include <vector>

namespace fault {

// Loading maps (.bt, .ot, messages), inserting frames, saving, URDF loads
// and link-set building.
std::vector<SweepCase> map_and_robot_cases();

// Every query kind on both engines, on a fresh context and on a used one.
std::vector<SweepCase> query_cases();

}  // namespace fault
