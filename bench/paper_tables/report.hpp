// Printing the tables in the paper's format, and the JSON output.
#pragma once

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace paper_tables {

// One row of a table: one pipeline on one scene and variant.  Times in ms.
struct TableRow {
    std::string table;     // "II"
    std::string pipeline;  // e.g. "octoprox direct"
    std::string scene;     // "H" or "F"
    std::string variant;   // "a" or "b"
    double t11_ms = 0.0;
    double t12_ms = 0.0;
    double tq_ms = 0.0;
    int queries = 0;
    std::string cpu;
    // The n of the columns T_1 + n T_q: Table II shows 10 and 100, Table
    // III (distance) 1.
    std::vector<int> totals_of_queries{10, 100};
    std::optional<double> tq_median_ms;  // when the queries differ (real map)
    std::optional<double> distance_m;    // distance rows: the minimum found

    double t1_ms() const { return t11_ms + t12_ms; }
    // T_1 + n T_q: the cost of n queries on one frame of sensor data.
    double t1_plus_n_queries_ms(int n) const { return t1_ms() + n * tq_ms; }
};

// `value` with 3 significant digits, without an exponent down to 1e-4.
std::string three_significant(double value);

// The rows under a title, with the columns T_{1,1}, T_{1,2}, T_q and
// T_1 + n T_q for the first row's totals_of_queries (10 and 100), in ms.
void print_table(std::ostream &out, const std::string &title, const std::vector<TableRow> &rows);

// Writes the rows as a JSON array of objects; false when the file fails.
bool write_json(const std::string &path, const std::vector<TableRow> &rows);

// The CPU's "model name" from /proc/cpuinfo, or "unknown".
std::string cpu_name();

// The 1, 5 and 15 minute load averages from /proc/loadavg, or "unknown":
// timings on a loaded machine are noisy, so the report says how loaded.
std::string load_average();

// The peak resident set size of this process, in MiB (getrusage).
double peak_rss_mib();

}  // namespace paper_tables
