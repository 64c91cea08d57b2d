// opx-frame-bench: the per-frame budget.  For a stream of
// frames (the real RGB-D frame with small sensor motions, and the
// generated room at 307,200 points), at 5, 2 and 1 cm: ingest (ray-cast
// and endpoints), then 1,000 PR2 collision queries at random reachable
// configurations and 10 distance queries, per frame, for octoprox (direct
// and amortized engines) and FCL + OctoMap, in one run (frame_run.hpp).
//   opx-frame-bench [--quick] [--json FILE] [--frames N] [--only real|room] [--queries N]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

#include "frame_report.hpp"
#include "pr2_scene.hpp"
#include "report.hpp"
#include "timing.hpp"

namespace frame_bench {
namespace {

constexpr uint64_t kConfigurationSeed = 0xF7A3E5u;

struct Options {
    bool quick = false;
    std::string json_path;
    int frames = 0;       // 0: the plan's
    std::string only;     // "", "real" or "room"
    int queries = 1000;   // collision configurations per frame
};

struct StreamPlan {
    std::string stream;
    RunPlan run;
};

// Frame counts and FCL distance samples keep the whole program under 10
// minutes on 2 cores: ray-cast ingest of the room costs seconds a frame at
// 1 and 2 cm in both libraries, and FCL's octree distance for the PR2 costs
// ~0.1-1 s a query at 1 cm.
std::vector<StreamPlan> full_plan() {
    return {{"real", {0.05, 10, 10, 10}}, {"real", {0.02, 6, 10, 10}}, {"real", {0.01, 4, 10, 3}},
            {"room", {0.05, 4, 10, 10}},  {"room", {0.02, 2, 10, 3}},  {"room", {0.01, 1, 10, 1}}};
}

std::vector<StreamPlan> quick_plan() { return {{"real", {0.05, 1, 2, 2}}, {"room", {0.05, 1, 2, 2}}}; }

void print_usage(FILE *out) {
    std::fprintf(out,
                 "usage: opx-frame-bench [--quick] [--json FILE] [--frames N] [--only real|room] [--queries N]\n"
                 "  --quick          smoke run: 1 frame per stream at 5 cm, 50 collision and 2 distance queries;\n"
                 "                   checks only (the pipelines agree on every collided flag)\n"
                 "  --json FILE      also write the results as JSON\n"
                 "  --frames N       frames per stream and resolution (default: the plan's, 1 to 10)\n"
                 "  --only S         only the stream S: real (the RGB-D frame) or room (generated)\n"
                 "  --queries N      collision configurations per frame (default 1000)\n"
                 "Needs the PR2 and the RGB-D frame of the shared data ($OPX_DATA_DIR, else ../shared/data);\n"
                 "exits 77 without them.\n");
}

bool parse_count(const char *text, int &out) {
    char *end = nullptr;
    const long value = std::strtol(text, &end, 10);
    if (end == text || *end != '\0' || value < 1 || value > 1000000) return false;
    out = static_cast<int>(value);
    return true;
}

bool parse_options(int argc, char **argv, Options &options) {
    bool queries_given = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--quick") options.quick = true;
        else if (arg == "--json" && has_value) options.json_path = argv[++i];
        else if (arg == "--frames" && has_value && parse_count(argv[++i], options.frames)) continue;
        else if (arg == "--queries" && has_value && parse_count(argv[++i], options.queries)) queries_given = true;
        else if (arg == "--only" && has_value && (std::strcmp(argv[i + 1], "real") == 0 || std::strcmp(argv[i + 1], "room") == 0))
            options.only = argv[++i];
        else {
            std::fprintf(stderr, "opx-frame-bench: bad argument '%s'\n", arg.c_str());
            return false;
        }
    }
    if (options.quick && !queries_given) options.queries = 50;
    return true;
}

// The robot on both sides, built once; their heap is reported.
struct Robots {
    paper_tables::OpxLinksetPtr links, links_amortized;
    std::unique_ptr<paper_tables::FclRobot> fcl;
    size_t heap_opx = 0, heap_fcl = 0;
};

Robots load_robots() {
    Robots robots;
    robots.heap_opx = measure_heap([&] { robots.links = paper_tables::load_pr2(); }).peak_above_start;
    opx_linkset *clone = nullptr;
    paper_tables::check_opx(opx_linkset_clone(robots.links.get(), &clone), "opx_linkset_clone");
    robots.links_amortized.reset(clone);
    robots.heap_fcl = measure_heap([&] { robots.fcl = std::make_unique<paper_tables::FclRobot>(robots.links.get()); })
                          .peak_above_start;
    return robots;
}

Stream make_stream(const std::string &name, const Robots &robots) {
    if (name == "room") return make_room_stream();
    return make_real_stream(paper_tables::data_root(), paper_tables::camera_pose(robots.links.get()));
}

void print_stream(const Stream &stream, const Robot &robot) {
    std::printf("\nstream %s: %s\n  %zu points (%zu finite); sensor moved by up to +-%.0f mm and +-%.0f mrad per "
                "axis each frame (seeded); PR2 root at (%.2f, %.2f, %.3f) m; %zu configurations (14 arm joints "
                "uniform within +-0.5 rad of the reaching pose, clamped to the URDF limits, seed 0x%llx)\n",
                stream.name.c_str(), stream.frame.source.c_str(), stream.frame.count, stream.frame.finite_count,
                kShift * 1000, kTurn * 1000, robot.base.position[0], robot.base.position[1], robot.base.position[2],
                robot.configurations.size(), static_cast<unsigned long long>(kConfigurationSeed));
    std::fflush(stdout);
}

std::vector<RunResult> run_plans(const Options &options, Robots &robots) {
    std::vector<RunResult> results;
    std::string current;
    Stream stream;
    Robot robot;
    for (StreamPlan plan : options.quick ? quick_plan() : full_plan()) {
        if (!options.only.empty() && plan.stream != options.only) continue;
        if (options.frames > 0) plan.run.frames = options.frames;
        if (plan.stream != current) {
            current = plan.stream;
            stream = make_stream(plan.stream, robots);
            robot = Robot{robots.links.get(), robots.links_amortized.get(), robots.fcl.get(), {}, stream.robot_base};
            robot.configurations = paper_tables::draw_reaching_configurations(robots.links.get(), options.queries,
                                                                              kConfigurationSeed, stream.robot_base);
            print_stream(stream, robot);
        }
        results.push_back(run_frames(stream, robot, plan.run));
        print_run(results.back());
    }
    return results;
}

int run(const Options &options) {
    const std::string missing = paper_tables::missing_pr2_data();
    if (!missing.empty()) {
        std::printf("opx-frame-bench: skipped: %s not found (set OPX_DATA_DIR to the shared data folder)\n",
                    missing.c_str());
        return 77;
    }
    ReportContext context;
    context.cpu = paper_tables::cpu_name();
    context.load_start = paper_tables::load_average();
    context.quick = options.quick;
    std::printf("opx-frame-bench (OctoProx %s)\nCPU: %s\nload average at start: %s\n", opx_version(),
                context.cpu.c_str(), context.load_start.c_str());
    const auto start = paper_tables::Clock::now();
    Robots robots = load_robots();
    context.robot_heap_opx = robots.heap_opx;
    context.robot_heap_fcl = robots.heap_fcl;
    std::printf("robot: the PR2 (URDF, every collision shape); heap: octoprox link set %.1f MiB, FCL objects %.1f MiB\n",
                robots.heap_opx / 1048576.0, robots.heap_fcl / 1048576.0);
    const std::vector<RunResult> results = run_plans(options, robots);
    context.seconds = paper_tables::milliseconds_between(start, paper_tables::Clock::now()) / 1000.0;
    context.load_end = paper_tables::load_average();
    context.peak_rss_mib = paper_tables::peak_rss_mib();
    std::printf("\nheap MiB: the high-water of the ray-cast map plus the pipeline's engine (queries, structure), "
                "counted at every operator new/delete (malloc_usable_size); process peak RSS (getrusage, all "
                "pipelines and maps together): %.1f MiB\nload average at end: %s; %.0f s\n",
                context.peak_rss_mib, context.load_end.c_str(), context.seconds);
    int status = 0;
    for (const RunResult &r : results) status |= r.checks.ok() ? 0 : 1;
    if (status != 0) std::printf("FAIL: the pipelines disagree (see MISMATCH above)\n");
    if (!options.json_path.empty() && !write_report_json(options.json_path, results, context)) {
        std::fprintf(stderr, "opx-frame-bench: cannot write %s\n", options.json_path.c_str());
        status = 1;
    }
    return status;
}

}  // namespace
}  // namespace frame_bench

int main(int argc, char **argv) {
    using namespace frame_bench;
    if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        print_usage(stdout);
        return 0;
    }
    Options options;
    if (!parse_options(argc, argv, options)) {
        print_usage(stderr);
        return 2;
    }
    try {
        return run(options);
    } catch (const std::exception &error) {
        std::fprintf(stderr, "opx-frame-bench: %s\n", error.what());
        return 1;
    }
}
