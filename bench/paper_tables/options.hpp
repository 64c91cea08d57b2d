// Command-line options of opx-paper-tables.
#pragma once

#include <string>

namespace paper_tables {

struct BenchOptions {
    std::string table;      // "I", "II", "III", "IV"
    int queries = 1000;     // N: T_q is the mean over N identical queries (III: 100)
    int repetitions = 10;   // T_{1,1} and T_{1,2} are medians over these
    bool quick = false;     // smoke run: 20 queries, 1 repetition
    std::string json_path;  // --json FILE; empty: no JSON
};

}  // namespace paper_tables
