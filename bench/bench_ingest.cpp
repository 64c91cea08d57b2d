// opx-bench-ingest: how fast one 640x480 frame goes into an occupancy map,
// OctoProx (1 and 2 threads) against OctoMap's own insertPointCloud: the
// first frame into a fresh map, and a later frame (the same frame into a
// map that holds it once).  Ray-cast rows carry the frame's ray steps and
// distinct cells, and the time per step.  Every run checks that its maps
// hold as many occupied and free leaves as OctoMap's (exit 1 otherwise).
//
//   opx-bench-ingest [--reps N] [--quick] [--generated] [--robot] [--data DIR] [--json FILE]
// --robot measures self-filtering instead (ingest_robot.hpp).
#include "bench_frame.hpp"
#include "bench_pipelines.hpp"
#include "ingest_robot.hpp"
#include "machine_probe.hpp"

#include <octoprox/octoprox.h>

#include <cstdint>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string>
#include <vector>

#include <sys/resource.h>

namespace {

struct Args {
    int reps = 5;
    bool quick = false;
    bool robot = false;
    bool generated = false;
    std::string data_dir;
    std::string json_path;
};

struct Row {
    double resolution;
    const char *mode;
    const char *frame;  // "first" (fresh map) or "later"
    bench::Pipeline pipeline;
    bench::RunResult result;
    double ratio;             // octoprox (1 thread) ms / this row's ms; 0 for that row
    double octomap_over_this; // OctoMap insertPointCloud ms / this row's ms (ray-cast rows)
    bench::RayWork work;      // ray-cast rows
    double ns_per_step() const { return work.steps ? result.median_ms() * 1e6 / double(work.steps) : 0.0; }
};

[[noreturn]] void usage(const char *program, int status) {
    std::fprintf(status ? stderr : stdout,
                 "usage: %s [--reps N] [--quick] [--generated] [--robot] [--data DIR] [--json FILE]\n"
                 "  --reps N     repetitions per row, median reported (default 5)\n"
                 "  --quick      smoke run: 1 repetition, 5 cm only\n"
                 "  --generated  use the synthetic room even when the real frame exists\n"
                 "  --robot      self-filtering instead: the PR2's arms rendered into the real frame,\n"
                 "               with and without the robot (needs the shared data; exits 77 without it)\n"
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
        else if (a == "--robot") args.robot = true;
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

// OctoProx's maps (one and two threads) hold as many occupied and free
// leaves as OctoMap's map of the same frame (results[2], the reference of
// the same semantics): a speed-up of a different map would be no speed-up.
// Throws when they do not.
void require_same_maps(const std::vector<bench::RunResult> &results, double resolution, const char *mode) {
    const bench::RunResult &octomap = results[2];
    for (size_t i = 0; i < 2; ++i)
        if (results[i].occupied != octomap.occupied || results[i].free != octomap.free)
            throw std::runtime_error("at " + std::to_string(resolution) + " m, " + mode + ", " +
                                     bench::pipeline_name(i == 0 ? bench::Pipeline::kOctoprox
                                                                 : bench::Pipeline::kOctoproxTwoThreads) +
                                     " has " + std::to_string(results[i].occupied) + " occupied and " +
                                     std::to_string(results[i].free) + " free leaves where OctoMap has " +
                                     std::to_string(octomap.occupied) + " and " + std::to_string(octomap.free));
}

// The rows of one resolution: ray-cast (first and later frame) and
// endpoints, ours then OctoMap's.
void run_resolution(const bench::Frame &frame, double resolution, int reps, std::vector<Row> &rows) {
    using bench::Pipeline;
    struct Plan {
        const char *mode;
        const char *frame;
        bool raycast, later;
        std::vector<Pipeline> references;
    };
    const Plan plans[] = {
        {"raycast", "first", true, false, {Pipeline::kOctomap, Pipeline::kOctomapDiscretize}},
        {"raycast", "later", true, true, {Pipeline::kOctomap}},
        {"endpoints", "first", false, false, {Pipeline::kOctomapEndpoints}}};
    const bench::RayWork work = bench::ray_work(frame, resolution);
    for (const Plan &plan : plans) {
        std::vector<Pipeline> pipelines = {Pipeline::kOctoprox, Pipeline::kOctoproxTwoThreads};
        pipelines.insert(pipelines.end(), plan.references.begin(), plan.references.end());
        const std::vector<bench::RunResult> results =
            bench::run_interleaved(pipelines, frame, resolution, plan.raycast, plan.later, reps);
        require_same_maps(results, resolution, plan.mode);
        const double ours_ms = results[0].median_ms();
        const double octomap_ms = plan.raycast ? results[2].median_ms() : 0.0;
        for (size_t i = 0; i < pipelines.size(); ++i) {
            const double ms = results[i].median_ms();
            const double ratio = i == 0 ? 0.0 : ours_ms / ms;
            rows.push_back({resolution, plan.mode, plan.frame, pipelines[i], results[i], ratio,
                            plan.raycast ? octomap_ms / ms : 0.0, plan.raycast ? work : bench::RayWork{}});
        }
    }
}

void print_table(const std::vector<Row> &rows, int reps) {
    std::printf("\n%-6s %-10s %-6s %-36s %10s %9s %9s %9s %11s %9s %10s\n", "res", "mode", "frame", "pipeline",
                "ms/frame", "occupied", "free", "B/leaf", "heap B/leaf", "ns/step", "octomap/x");
    std::printf("%-6s %-10s %-6s %-36s %10s\n", "", "", "", "", reps > 1 ? "(median)" : "(1 rep)");
    for (const Row &r : rows) {
        char speedup[32] = "-", per_step[32] = "-";
        if (r.octomap_over_this > 0) std::snprintf(speedup, sizeof speedup, "%.2f", r.octomap_over_this);
        if (r.work.steps > 0) std::snprintf(per_step, sizeof per_step, "%.2f", r.ns_per_step());
        std::printf("%-6s %-10s %-6s %-36s %10.1f %9llu %9llu %9.1f %11.1f %9s %10s\n",
                    (std::to_string(int(r.resolution * 100 + 0.5)) + "cm").c_str(), r.mode, r.frame,
                    bench::pipeline_name(r.pipeline), r.result.median_ms(), (unsigned long long)r.result.occupied,
                    (unsigned long long)r.result.free, r.result.bytes_per_leaf(), r.result.heap_bytes_per_leaf(),
                    per_step, speedup);
    }
    std::printf("\nray-cast work per frame (OctoMap's computeRayKeys):\n");
    for (const Row &r : rows)
        if (r.work.steps > 0 && r.pipeline == bench::Pipeline::kOctoprox && std::string(r.frame) == "first")
            std::printf("  %2d cm: %llu ray steps, %llu distinct cells\n", int(r.resolution * 100 + 0.5),
                        (unsigned long long)r.work.steps, (unsigned long long)r.work.distinct_cells);
}

std::string json_number(double value) { return value > 0 ? std::to_string(value) : "null"; }

// The machine the rows were measured on.
struct Machine {
    std::string cpu;
    bench::ThreadSpeed at_start, at_end;  // integer additions a ns (machine_probe.hpp)
};

void write_json(const std::string &path, const std::vector<Row> &rows, const bench::Frame &frame, int reps,
                const Machine &machine) {
    std::FILE *out = std::fopen(path.c_str(), "w");
    if (out == nullptr) throw std::runtime_error("cannot write " + path);
    const std::string speeds = bench::thread_speed_json_fields(machine.at_start, machine.at_end);
    std::fprintf(out, "[\n");
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row &r = rows[i];
        const bool two = r.pipeline == bench::Pipeline::kOctoproxTwoThreads;
        std::fprintf(out,
                     "  {\"resolution\": %g, \"mode\": \"%s\", \"frame\": \"%s\", \"pipeline\": \"%s\", "
                     "\"threads\": %d, \"median_ms\": %.3f, \"reps\": %d, \"occupied\": %llu, \"free\": %llu, "
                     "\"memory_bytes\": %llu, \"bytes_per_leaf\": %.2f, \"heap_bytes\": %llu, "
                     "\"heap_bytes_per_leaf\": %.2f, \"octoprox_over_this\": %s, \"octomap_over_this\": %s, "
                     "\"ray_steps\": %llu, \"distinct_cells\": %llu, \"ns_per_step\": %s, "
                     "\"points\": %zu, \"finite_points\": %zu, \"cpu\": \"%s\", %s}%s\n",
                     r.resolution, r.mode, r.frame, bench::pipeline_name(r.pipeline), two ? 2 : 1,
                     r.result.median_ms(), reps, (unsigned long long)r.result.occupied,
                     (unsigned long long)r.result.free, (unsigned long long)r.result.memory_bytes,
                     r.result.bytes_per_leaf(), (unsigned long long)r.result.heap_bytes,
                     r.result.heap_bytes_per_leaf(), json_number(r.ratio).c_str(),
                     json_number(r.octomap_over_this).c_str(), (unsigned long long)r.work.steps,
                     (unsigned long long)r.work.distinct_cells, json_number(r.ns_per_step()).c_str(), frame.count,
                     frame.finite_count, machine.cpu.c_str(), speeds.c_str(), i + 1 < rows.size() ? "," : "");
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
        if (args.robot) {
            bench::RobotRunOptions robot;
            robot.data_dir = args.data_dir, robot.json_path = args.json_path, robot.cpu = cpu_name();
            robot.quick = args.quick;
            if (args.reps != 5) robot.reps = args.reps;
            return bench::run_robot_rows(robot);
        }
        const bench::Frame frame = bench::load_frame(args.data_dir, args.generated);
        std::printf("OctoProx %s ingest benchmark\n", opx_version());
        std::printf("frame: %s\n       %ux%u = %zu points, %zu finite; %d repetition(s) per row, fresh tree each\n",
                    frame.source.c_str(), frame.width, frame.height, frame.count, frame.finite_count, args.reps);
        Machine machine;
        machine.cpu = cpu_name();
        machine.at_start = bench::measure_thread_speed();
        std::vector<Row> rows;
        run_resolution(frame, 0.05, args.reps, rows);
        if (!args.quick) run_resolution(frame, 0.02, args.reps, rows);
        machine.at_end = bench::measure_thread_speed();
        print_table(rows, args.reps);
        if (!args.json_path.empty()) {
            write_json(args.json_path, rows, frame, args.reps, machine);
            std::printf("\nrows written to %s\n", args.json_path.c_str());
        }
        std::printf("\ncpu: %s\npeak RSS: %.1f MiB\n", machine.cpu.c_str(), peak_rss_kib() / 1024.0);
        bench::print_thread_speeds(machine.at_start, machine.at_end);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "opx-bench-ingest: %s\n", e.what());
        return 1;
    }
    return 0;
}
