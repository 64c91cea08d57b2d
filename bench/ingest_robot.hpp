// opx-bench-ingest --robot: self-filtering's cost.  The PR2's arms rendered
// into the real depth frame from its head camera (tests/render), inserted
// as a depth image with and without the robot (robot_padding 2 cm), at 5
// and 2 cm, on 1 and 2 threads, the two pipelines alternating.
#pragma once

#include "machine_probe.hpp"

#include <string>

namespace bench {

struct RobotRunOptions {
    std::string data_dir;
    std::string json_path;  // "": no JSON
    std::string cpu;
    int reps = 9;
    bool quick = false;  // 1 repetition, 5 cm only
};

// Prints the table (and writes the JSON rows); returns the exit status (77
// without the shared data).
int run_robot_rows(const RobotRunOptions &options);

}  // namespace bench
