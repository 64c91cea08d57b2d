// The paper's tables, one source file each (table2.cpp, ...).
#pragma once

#include <string>
#include <vector>

#include "options.hpp"
#include "report.hpp"

namespace paper_tables {

// Each prints its tables, appends its rows, and returns 0, or 1 when a
// correctness check failed (the pipelines disagree: "MISMATCH").

// Table I: FCL's default and Morton broad-phase builds against OctoProx's
// amortized engine (unrefined, refined) and direct engine, collision in
// scene F (variant a) at 7,784 cells, then 25k, 100k, 300k random cells.
// Writes its own JSON rows (options.json_path), not through `rows`.
int run_table1(const BenchOptions &options, const std::string &cpu);

// Table II: collision, 300 objects against a 7,784-cell octree; pipelines
// FCL boxes + DynamicAABBTree, FCL octree, octoprox direct; scenes H
// (hits) and F (free); variants (a) primitives and (b) meshes.
int run_table2(const BenchOptions &options, const std::string &cpu, std::vector<TableRow> &rows);

// Table III: distance, the same scenes and pipelines: the full minimum in
// scene F, the early stop at 0 in scene H; then single-sphere distance
// queries in the real map geb079.bt (skipped when the data is absent).
int run_table3(const BenchOptions &options, const std::string &cpu, std::vector<TableRow> &rows);

// Table IV: the PR2 against an octree from the real RGB-D frame (about
// 25,000 cells): collision (a set of colliding configurations) and distance
// (a set of collision-free ones); pipelines FCL boxes + DynamicAABBTree,
// FCL octree, octoprox direct, octoprox amortized.  Without the shared
// data it prints why and returns 0 (77 with --quick: ctest's "skipped").
int run_table4(const BenchOptions &options, const std::string &cpu, std::vector<TableRow> &rows);

}  // namespace paper_tables
