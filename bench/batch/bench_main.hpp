// The command line and the frame of opx-bench-batch and opx-bench-world:
// the same options (--quick, --json FILE, --configurations N and, where
// the program takes it, --rounds N), the same skip without the shared
// data (exit 77), header, table, JSON file and exit codes (2 bad
// arguments, 1 an error or answers that disagree).
#pragma once

#include "batch_report.hpp"

#include <cstddef>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace batch_bench {

struct BenchOptions {
    bool quick = false;  // 100 configurations (unless given) and one round
    size_t configurations = 10000;
    int rounds = 3;
};

struct BenchOutcome {
    std::vector<Row> rows;
    bool agree = true;  // false: a library defect, the run fails
};

struct BenchProgram {
    const char *name;  // "opx-bench-batch"
    bool takes_rounds;
    void (*print_usage)(FILE *out);
    const char *disagreement;  // printed after "FAIL: " when the answers disagree
};

// Runs the program: --help, the options (defaults as given), the data
// check, `run`, the report; returns the exit code.
int bench_main(const BenchProgram &program, int argc, char **argv, BenchOptions defaults,
               const std::function<BenchOutcome(const BenchOptions &)> &run);

}  // namespace batch_bench
