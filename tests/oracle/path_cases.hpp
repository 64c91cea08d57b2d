// Hand-made path cases: a cell swept by two waypoints counted once (the
// union of its boxes, not the sum), bad arguments, zero waypoints, the link
// set left unmoved, and a path query after its link set was replaced.
#pragma once

#include "oracle_path_check.hpp"

namespace oracle {

void run_path_cases(PathReport &report);

}  // namespace oracle
