// One run of opx-bench-batch: every robot on every map through every
// pipeline, the rows of the report, and whether the batch call answered
// every configuration as the single calls did.
#pragma once

#include <vector>

#include "batch_report.hpp"

namespace batch_bench {

struct RunOptions {
    bool quick = false;
    size_t configurations = 10000;  // per robot and map
    // Each a few seconds (FCL's pass over the set); the median of five
    // holds through a shared machine's slow spells of that length.
    int rounds = 5;
};

struct RunResult {
    std::vector<Row> rows;
    bool agree = true;
};

RunResult run_all(const RunOptions &options);

}  // namespace batch_bench
