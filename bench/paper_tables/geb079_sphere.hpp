// After Table III: single-sphere distance queries in a real map,
// geb079.bt (from $OPX_DATA_DIR, else the shared data folder), OctoProx
// against FCL's octree distance, with a brute-force reference.
#pragma once

#include <string>
#include <vector>

#include "options.hpp"
#include "report.hpp"

namespace paper_tables {

// Prints the comparison and appends two rows (scene "geb079 sphere").
// Returns 1 when octoprox disagrees with the brute-force reference, else 0
// (also when the map is absent: a message says it was skipped).
int run_geb079_sphere(const BenchOptions &options, const std::string &cpu, std::vector<TableRow> &rows);

}  // namespace paper_tables
