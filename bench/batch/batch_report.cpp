#include "batch_report.hpp"

#include <cmath>
#include <cstdio>

namespace batch_bench {
namespace {

std::string json_string(const std::string &text) {
    std::string out = "\"";
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}

std::string json_number(double value) {
    if (!std::isfinite(value)) return "null";
    char text[64];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

}  // namespace

void print_rows(const std::vector<Row> &rows) {
    std::printf("\n%-14s %-20s %-24s %12s  %s\n", "robot", "map", "pipeline", "us/config", "other");
    for (const Row &row : rows) {
        std::printf("%-14s %-20s %-24s %12.3f ", row.robot.c_str(), row.map.c_str(), row.pipeline.c_str(),
                    row.us_per_configuration);
        for (const auto &field : row.fields) std::printf(" %s=%.4g", field.first.c_str(), field.second);
        std::printf("\n");
    }
    std::fflush(stdout);
}

bool write_rows_json(const std::string &path, const std::vector<Row> &rows, const Machine &machine) {
    FILE *out = std::fopen(path.c_str(), "w");
    if (out == nullptr) return false;
    const std::string speeds = bench::thread_speed_json_fields(machine.at_start, machine.at_end);
    std::fprintf(out, "[\n");
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &row = rows[i];
        std::fprintf(out, "  {\"robot\": %s, \"map\": %s, \"pipeline\": %s, \"us_per_configuration\": %s",
                     json_string(row.robot).c_str(), json_string(row.map).c_str(), json_string(row.pipeline).c_str(),
                     json_number(row.us_per_configuration).c_str());
        for (const auto &field : row.fields)
            std::fprintf(out, ", %s: %s", json_string(field.first).c_str(), json_number(field.second).c_str());
        std::fprintf(out, ", \"cpu\": %s, \"load_average\": %s, %s}%s\n", json_string(machine.cpu).c_str(),
                     json_string(machine.load).c_str(), speeds.c_str(), i + 1 < rows.size() ? "," : "");
    }
    std::fprintf(out, "]\n");
    return std::fclose(out) == 0;
}

}  // namespace batch_bench
