// One robot in one map for opx-bench-plan: random valid start and goal
// pairs, each solved by RRTConnect twice with the same seeded samples,
// once with OctoProx's checkers (opx_ompl, examples/ompl) and once with
// FCL's (plan_checkers.hpp), the two interleaved query by query.
#pragma once

#include "bench_scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace plan_bench {

struct PlanOptions {
    size_t queries = 100;
    double budget = 10.0;  // seconds a plan may take before it counts as failed
    uint64_t seed = 1;
};

// The figures of one checker over the queries.
struct PlanRow {
    std::string planner = "RRTConnect", checker, robot, map;
    size_t queries = 0, solved = 0;
    double median_ms = 0.0, p95_ms = 0.0;
    double configurations_per_s = 0.0;  // checked while planning, over all queries
    uint64_t configurations = 0;
};

struct PairResult {
    PlanRow octoprox, fcl;
    size_t same_steps = 0;  // queries whose two plans checked the same configurations
};

// `planned`: the model indices of the joints the planner moves.
PairResult run_pair(batch_bench::Robot &robot, const std::string &robot_name, batch_bench::Scene &scene,
                    const opx_pose &base, const std::vector<uint32_t> &planned, const PlanOptions &options);

// The PR2's right arm joints, and every joint of a robot.
std::vector<uint32_t> pr2_right_arm(const opx_linkset *pr2);
std::vector<uint32_t> all_moving_joints(const opx_linkset *robot);

}  // namespace plan_bench
