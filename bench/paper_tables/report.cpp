#include "report.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace paper_tables {
namespace {

// The decimal exponent of `value` after rounding to 3 significant digits
// (9.996 rounds to 10.0: exponent 1, not 0).
int rounded_exponent(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2e", value);
    const char *e = std::strchr(buffer, 'e');
    return e != nullptr ? std::atoi(e + 1) : 0;
}

std::string json_string(const std::string &text) {
    std::string quoted = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') quoted += '\\';
        if (static_cast<unsigned char>(c) < 0x20) continue;  // no control characters in our strings
        quoted += c;
    }
    return quoted + "\"";
}

std::string json_number(double value, int significant_digits = 6) {
    char buffer[48];
    std::snprintf(buffer, sizeof buffer, "%.*g", significant_digits, value);
    return buffer;
}

// "T1_plus_Tq_ms" for n = 1, "T1_plus_10Tq_ms" for n = 10.
std::string total_key(int n) {
    return "T1_plus_" + (n == 1 ? std::string() : std::to_string(n)) + "Tq_ms";
}

void write_json_row(std::ostream &out, const TableRow &row) {
    out << "  {\"table\": " << json_string(row.table) << ", \"pipeline\": " << json_string(row.pipeline)
        << ", \"scene\": " << json_string(row.scene) << ", \"variant\": " << json_string(row.variant)
        << ", \"T11_ms\": " << json_number(row.t11_ms) << ", \"T12_ms\": " << json_number(row.t12_ms)
        << ", \"Tq_ms\": " << json_number(row.tq_ms);
    if (row.tq_median_ms) out << ", \"Tq_median_ms\": " << json_number(*row.tq_median_ms);
    for (int n : row.totals_of_queries)
        out << ", " << json_string(total_key(n)) << ": " << json_number(row.t1_plus_n_queries_ms(n));
    if (row.distance_m) out << ", \"distance_m\": " << json_number(*row.distance_m, 12);
    out << ", \"queries\": " << row.queries << ", \"cpu\": " << json_string(row.cpu) << "}";
}

// "T_1+T_q" for n = 1, "T_1+10T_q" for n = 10.
std::string total_column(int n) { return "T_1+" + (n == 1 ? std::string() : std::to_string(n)) + "T_q"; }

std::string padded(const std::string &text, size_t width) {
    return text.size() >= width ? text + " " : text + std::string(width - text.size(), ' ');
}

constexpr size_t kNameWidth = 30;
constexpr size_t kNumberWidth = 13;

}  // namespace

std::string three_significant(double value) {
    if (value == 0.0 || !std::isfinite(value)) return value == 0.0 ? "0" : "nan";
    const int exponent = rounded_exponent(value);
    char buffer[48];
    if (exponent < -4 || exponent > 6)
        std::snprintf(buffer, sizeof buffer, "%.2e", value);
    else
        std::snprintf(buffer, sizeof buffer, "%.*f", std::max(0, 2 - exponent), value);
    return buffer;
}

void print_table(std::ostream &out, const std::string &title, const std::vector<TableRow> &rows) {
    out << title << "\n";
    const std::vector<int> totals = rows.empty() ? std::vector<int>() : rows.front().totals_of_queries;
    out << padded("pipeline", kNameWidth);
    for (const char *column : {"T_{1,1}", "T_{1,2}", "T_q"}) out << padded(column, kNumberWidth);
    for (int n : totals) out << padded(total_column(n), kNumberWidth);
    out << "\n";
    for (const TableRow &row : rows) {
        out << padded(row.pipeline, kNameWidth);
        for (double value : {row.t11_ms, row.t12_ms, row.tq_ms}) out << padded(three_significant(value), kNumberWidth);
        for (int n : totals) out << padded(three_significant(row.t1_plus_n_queries_ms(n)), kNumberWidth);
        out << "\n";
    }
}

bool write_json(const std::string &path, const std::vector<TableRow> &rows) {
    std::ofstream out(path);
    if (!out) return false;
    out << "[\n";
    for (size_t i = 0; i < rows.size(); ++i) {
        write_json_row(out, rows[i]);
        out << (i + 1 < rows.size() ? ",\n" : "\n");
    }
    out << "]\n";
    return static_cast<bool>(out);
}

std::string cpu_name() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
        if (line.rfind("model name", 0) != 0) continue;
        const size_t colon = line.find(':');
        if (colon == std::string::npos) break;
        const size_t start = line.find_first_not_of(" \t", colon + 1);
        return start == std::string::npos ? "unknown" : line.substr(start);
    }
    return "unknown";
}

std::string load_average() {
    std::ifstream loadavg("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(loadavg >> one >> five >> fifteen)) return "unknown";
    return one + " " + five + " " + fifteen;
}

double peak_rss_mib() {
    struct rusage usage;
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0.0;
    return usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace paper_tables
