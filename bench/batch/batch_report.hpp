// The rows of opx-bench-batch: printed as a table and written as a JSON
// list of objects with the fields robot, map, pipeline,
// us_per_configuration and any row's own (ns_per_sphere, ns_per_call,
// motions_per_second, ...), each with the CPU.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "machine_probe.hpp"

namespace batch_bench {

struct Row {
    std::string robot, map, pipeline;
    double us_per_configuration = 0.0;
    std::vector<std::pair<std::string, double>> fields;  // the row's own, in order
};

void print_rows(const std::vector<Row> &rows);
// Where the rows were measured: the CPU, the load average, and the
// threads' speed at the start and the end (machine_probe.hpp).
struct Machine {
    std::string cpu, load;
    bench::ThreadSpeed at_start, at_end;
};

bool write_rows_json(const std::string &path, const std::vector<Row> &rows, const Machine &machine);

}  // namespace batch_bench
