// One run of opx-bench-world: for each object count, the PR2's
// configurations checked against the objects alone, the real map alone and
// both (octoprox, direct engine: forward kinematics then opx_query_collide
// per configuration, a world set on the context; and the map with the
// objects in batch calls on 1 and 2 threads), and against the same objects
// by FCL's collision manager (the robot's objects placed at the
// configuration's link poses, then its manager against the objects').
// Rounds are interleaved; pose updates and queries are timed apart.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "batch_report.hpp"

namespace world_bench {

struct RunOptions {
    bool quick = false;
    size_t configurations = 10000;
    int rounds = 5;
    std::vector<size_t> object_counts{10, 100, 1000};
};

struct RunResult {
    std::vector<batch_bench::Row> rows;
    // For every configuration, the answer with the map and the objects is
    // the union of the two alone, and the batch call's is the single
    // calls' (a library defect otherwise).
    bool composition_agrees = true;
};

RunResult run_all(const RunOptions &options);

}  // namespace world_bench
