// opx-bench-batch: many configurations per call.  The PR2 and a 7-joint
// arm at random reachable configurations against the real 2 cm frame and
// the generated room: the one-call-per-configuration way, the batch call on
// 1 and 2 threads, and FCL (world + self-collision, its FK untimed), in
// microseconds per configuration; motion checks per second; and the
// sphere rows (a 50-sphere arm through the batch call, one sphere per
// call).
//   opx-bench-batch [--quick] [--json FILE] [--configurations N]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "batch_run.hpp"
#include "pr2_scene.hpp"
#include "report.hpp"
#include "batch_report.hpp"

namespace batch_bench {
namespace {

void print_usage(FILE *out) {
    std::fprintf(out,
                 "usage: opx-bench-batch [--quick] [--json FILE] [--configurations N]\n"
                 "  --quick             smoke run: 100 configurations, one round; checks that the batch call\n"
                 "                      answers as the single calls do\n"
                 "  --json FILE         also write the rows as a JSON list\n"
                 "  --configurations N  configurations per robot and map (default 10000)\n"
                 "Needs the PR2 and the RGB-D frame of the shared data ($OPX_DATA_DIR, else ../shared/data);\n"
                 "exits 77 without them.\n");
}

bool parse_options(int argc, char **argv, RunOptions &options, std::string &json_path) {
    bool counted = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        if (arg == "--quick") {
            options.quick = true;
        } else if (arg == "--json" && has_value) {
            json_path = argv[++i];
        } else if (arg == "--configurations" && has_value) {
            const long n = std::strtol(argv[++i], nullptr, 10);
            if (n < 10 || n > 1000000) return false;
            options.configurations = static_cast<size_t>(n);
            counted = true;
        } else {
            std::fprintf(stderr, "opx-bench-batch: bad argument '%s'\n", arg.c_str());
            return false;
        }
    }
    if (options.quick) {
        if (!counted) options.configurations = 100;
        options.rounds = 1;
    }
    return true;
}

int run(int argc, char **argv) {
    RunOptions options;
    std::string json_path;
    if (!parse_options(argc, argv, options, json_path)) {
        print_usage(stderr);
        return 2;
    }
    const std::string missing = paper_tables::missing_pr2_data();
    if (!missing.empty()) {
        std::printf("opx-bench-batch: skipped: %s not found (set OPX_DATA_DIR to the shared data folder)\n",
                    missing.c_str());
        return 77;
    }
    const std::string cpu = paper_tables::cpu_name(), load = paper_tables::load_average();
    std::printf("opx-bench-batch (OctoProx %s)\nCPU: %s\nload average at start: %s\n", opx_version(), cpu.c_str(),
                load.c_str());
    const RunResult result = run_all(options);
    print_rows(result.rows);
    std::printf("load average at end: %s\n", paper_tables::load_average().c_str());
    if (!json_path.empty() && !write_rows_json(json_path, result.rows, cpu, load)) {
        std::fprintf(stderr, "opx-bench-batch: cannot write %s\n", json_path.c_str());
        return 1;
    }
    if (!result.agree) std::printf("FAIL: the batch call and the single calls disagree (see MISMATCH above)\n");
    return result.agree ? 0 : 1;
}

}  // namespace
}  // namespace batch_bench

int main(int argc, char **argv) {
    if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        batch_bench::print_usage(stdout);
        return 0;
    }
    try {
        return batch_bench::run(argc, argv);
    } catch (const std::exception &error) {
        std::fprintf(stderr, "opx-bench-batch: %s\n", error.what());
        return 1;
    }
}
