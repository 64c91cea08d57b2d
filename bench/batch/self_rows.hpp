// The self-collision rows of opx-bench-batch: the robot against itself
// alone, one C call per configuration after its pose update (untimed), at
// the batch's configurations: opx_query_self_collide (yes or no, stopping
// at the first touching pair), opx_query_self_distance (the nearest pair,
// no cutoff), and FCL's self-collision over the same enabled pairs (its
// objects placed untimed).
#pragma once

#include "configurations.hpp"
#include "fcl_check.hpp"

namespace batch_bench {

struct SelfTiming {
    double collide_us = 0.0, distance_us = 0.0, fcl_collide_us = 0.0;  // per configuration, median round
    size_t configurations = 0, distance_configurations = 0;
    size_t collided = 0, fcl_collided = 0, differ = 0;  // configurations; differ: where the two disagree
};

// Distance over the first `distance_count` configurations only (it costs
// far more per call).
SelfTiming time_self_calls(Robot &robot, const ConfigurationSet &set, FclCheck &fcl, size_t distance_count,
                           int rounds);

}  // namespace batch_bench
