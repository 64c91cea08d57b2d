// The cost part of a path's comparison (oracle_path_check.hpp): total cost,
// number of swept cells and the costliest boxes kept, against the swept
// cost oracle (oracle_swept_cost.hpp); on a mismatch, the cells only one
// side has, with the oracle's smallest gap to each.
#pragma once

#include "oracle_path_check.hpp"
#include "oracle_swept_cost.hpp"

namespace oracle {

// The cost rule of a path request (its threshold, policy, probability and
// region; the default region from the scene's leaves).
CostRule path_cost_rule(const PathCase &path_case);

// The case, its request and robot, for a mismatch message.
std::string describe_path_case(const PathCase &path_case);

// `cost` is the oracle's (nullptr without compute_cost).
void compare_path_cost(opx_query *query, const opx_linkset *links, const PathCase &path_case,
                       const SweptCost *cost, const opx_path_result &result, PathReport &report);

}  // namespace oracle
