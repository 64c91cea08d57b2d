// opx-bench-ingest: how fast one 640x480 frame goes into an occupancy map,
// OctoProx against OctoMap's own insertPointCloud, on fresh trees.
//
//   opx-bench-ingest [--reps N] [--quick] [--generated] [--data DIR] [--json FILE]
#include "bench_frame.hpp"
#include "bench_pipelines.hpp"

#include <octoprox/octoprox.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace {

struct Args {
    int reps = 5;
    bool quick = false;
    bool generated = false;
    std::string data_dir;
    std::string json_path;
};

struct Row {
    double resolution;
    const char *mode;
    bench::Pipeline pipeline;
    bench::RunResult result;
    double ratio;  // octoprox ms / this row's ms; 0 for the octoprox row
};

[[noreturn]] void usage(const char *program, int status) {
    std::fprintf(status ? stderr : stdout,
                 "usage: %s [--reps N] [--quick] [--generated] [--data DIR] [--json FILE]\n"
                 "  --reps N     repetitions per row, median reported (default 5)\n"
                 "  --quick      smoke run: 1 repetition, 5 cm only\n"
                 "  --generated  use the synthetic room even when the real frame exists\n"
                 "  --data DIR   shared data folder (default $OPX_DATA_DIR, else the source tree's)\n"
                 "  --json FILE  also write the rows as a JSON array\n",
                 program);
    std::exit(status);
}

Args parse_args(int argc, char **argv) {
    Args args;
    const char *env = std::getenv("OPX_DATA_DIR");
    args.data_dir = env != nullptr && env[0] != '\0' ? env : OPX_DEFAULT_DATA_DIR;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const bool has_value = i + 1 < argc;
        if (a == "--quick") args.quick = true;
        else if (a == "--generated") args.generated = true;
        else if (a == "--reps" && has_value) args.reps = std::atoi(argv[++i]);
        else if (a == "--data" && has_value) args.data_dir = argv[++i];
        else if (a == "--json" && has_value) args.json_path = argv[++i];
        else if (a == "--help" || a == "-h") usage(argv[0], 0);
        else usage(argv[0], 2);
    }
    if (args.quick) args.reps = 1;
    if (args.reps < 1) usage(argv[0], 2);
    return args;
}

// The rows of one resolution: ray-cast and endpoints, ours then OctoMap's.
void run_resolution(const bench::Frame &frame, double resolution, int reps, std::vector<Row> &rows) {
    using bench::Pipeline;
    struct Plan {
        const char *mode;
        bool raycast;
        std::vector<Pipeline> references;
    };
    const Plan plans[] = {{"raycast", true, {Pipeline::kOctomap, Pipeline::kOctomapDiscretize}},
                          {"endpoints", false, {Pipeline::kOctomapEndpoints}}};
    for (const Plan &plan : plans) {
        std::vector<Pipeline> pipelines = {Pipeline::kOctoprox};
        pipelines.insert(pipelines.end(), plan.references.begin(), plan.references.end());
        const std::vector<bench::RunResult> results =
            bench::run_interleaved(pipelines, frame, resolution, plan.raycast, reps);
        const double ours_ms = results[0].median_ms();
        for (size_t i = 0; i < pipelines.size(); ++i) {
            const double ratio = i == 0 ? 0.0 : ours_ms / results[i].median_ms();
            rows.push_back({resolution, plan.mode, pipelines[i], results[i], ratio});
        }
    }
}

void print_table(const std::vector<Row> &rows, int reps) {
    std::printf("\n%-6s %-10s %-36s %10s %10s %10s %9s %11s %14s\n", "res", "mode", "pipeline", "ms/frame",
                "occupied", "free", "B/leaf", "heap B/leaf", "octoprox/this");
    std::printf("%-6s %-10s %-36s %10s\n", "", "", "", reps > 1 ? "(median)" : "(1 rep)");
    for (const Row &r : rows) {
        char ratio[32] = "-";
        if (r.ratio > 0) std::snprintf(ratio, sizeof ratio, "%.2f", r.ratio);
        std::printf("%-6s %-10s %-36s %10.1f %10llu %10llu %9.1f %11.1f %14s\n",
                    (std::to_string(int(r.resolution * 100 + 0.5)) + "cm").c_str(), r.mode,
                    bench::pipeline_name(r.pipeline), r.result.median_ms(), (unsigned long long)r.result.occupied,
                    (unsigned long long)r.result.free, r.result.bytes_per_leaf(), r.result.heap_bytes_per_leaf(),
                    ratio);
    }
}

void write_json(const std::string &path, const std::vector<Row> &rows, const bench::Frame &frame, int reps) {
    std::FILE *out = std::fopen(path.c_str(), "w");
    if (out == nullptr) throw std::runtime_error("cannot write " + path);
    std::fprintf(out, "[\n");
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &r = rows[i];
        std::fprintf(out,
                     "  {\"resolution\": %g, \"mode\": \"%s\", \"pipeline\": \"%s\", \"median_ms\": %.3f, "
                     "\"reps\": %d, \"occupied\": %llu, \"free\": %llu, \"memory_bytes\": %llu, "
                     "\"bytes_per_leaf\": %.2f, \"heap_bytes\": %llu, \"heap_bytes_per_leaf\": %.2f, "
                     "\"octoprox_over_this\": %s, \"points\": %zu, \"finite_points\": %zu}%s\n",
                     r.resolution, r.mode, bench::pipeline_name(r.pipeline), r.result.median_ms(), reps,
                     (unsigned long long)r.result.occupied, (unsigned long long)r.result.free,
                     (unsigned long long)r.result.memory_bytes, r.result.bytes_per_leaf(),
                     (unsigned long long)r.result.heap_bytes, r.result.heap_bytes_per_leaf(), r.ratio > 0 ? std::to_string(r.ratio).c_str() : "null", frame.count, frame.finite_count,
                     i + 1 < rows.size() ? "," : "");
    }
    std::fprintf(out, "]\n");
    std::fclose(out);
}

std::string cpu_name() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind("model name", 0) == 0) {
            const size_t colon = line.find(':');
            if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
        }
    }
    return "unknown";
}

long peak_rss_kib() {
    struct rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;  // kilobytes on Linux
}

}  // namespace

int main(int argc, char **argv) {
    const Args args = parse_args(argc, argv);
    try {
        const bench::Frame frame = bench::load_frame(args.data_dir, args.generated);
        std::printf("OctoProx %s ingest benchmark\n", opx_version());
        std::printf("frame: %s\n       %ux%u = %zu points, %zu finite; %d repetition(s) per row, fresh tree each\n",
                    frame.source.c_str(), frame.width, frame.height, frame.count, frame.finite_count, args.reps);
        std::vector<Row> rows;
        run_resolution(frame, 0.05, args.reps, rows);
        if (!args.quick) run_resolution(frame, 0.02, args.reps, rows);
        print_table(rows, args.reps);
        if (!args.json_path.empty()) {
            write_json(args.json_path, rows, frame, args.reps);
            std::printf("\nrows written to %s\n", args.json_path.c_str());
        }
        std::printf("\ncpu: %s\npeak RSS: %.1f MiB\n", cpu_name().c_str(), peak_rss_kib() / 1024.0);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "opx-bench-ingest: %s\n", e.what());
        return 1;
    }
    return 0;
}
