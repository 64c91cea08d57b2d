// opx-bench-world: the PR2 among known objects.  10,000 reaching
// configurations checked against 10, 100 and 1,000 random objects (boxes,
// cylinders, spheres, a tenth of them as meshes; the same 10 within the
// arms' reach, the others around them), the real 2 cm RGB-D frame, and both (octoprox, direct engine, forward
// kinematics and one opx_query_collide per configuration; batch calls),
// next to FCL's collision manager on the same objects.  Microseconds per
// configuration, pose updates and queries apart.
//   opx-bench-world [--quick] [--json FILE] [--configurations N] [--rounds N]
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "pr2_scene.hpp"
#include "report.hpp"
#include "world_run.hpp"

namespace world_bench {
namespace {

void print_usage(FILE *out) {
    std::fprintf(out,
                 "usage: opx-bench-world [--quick] [--json FILE] [--configurations N] [--rounds N]\n"
                 "  --quick             smoke run: 100 configurations, one round; checks that the answer with\n"
                 "                      the map and the objects is the union of the two alone, and that the\n"
                 "                      batch call answers as the single calls do\n"
                 "  --json FILE         also write the rows as a JSON list\n"
                 "  --configurations N  PR2 configurations (default 10000)\n"
                 "  --rounds N          timed rounds of every pipeline (default 5)\n"
                 "Needs the PR2 and the RGB-D frame of the shared data ($OPX_DATA_DIR, else ../shared/data);\n"
                 "exits 77 without them.\n");
}

bool parse_count(const char *text, long low, long high, long &out) {
    char *end = nullptr;
    out = std::strtol(text, &end, 10);
    return end != text && *end == '\0' && out >= low && out <= high;
}

bool parse_options(int argc, char **argv, RunOptions &options, std::string &json_path) {
    bool counted = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const bool has_value = i + 1 < argc;
        long n = 0;
        if (arg == "--quick") {
            options.quick = true;
        } else if (arg == "--json" && has_value) {
            json_path = argv[++i];
        } else if (arg == "--configurations" && has_value && parse_count(argv[++i], 10, 1000000, n)) {
            options.configurations = static_cast<size_t>(n);
            counted = true;
        } else if (arg == "--rounds" && has_value && parse_count(argv[++i], 1, 100, n)) {
            options.rounds = static_cast<int>(n);
        } else {
            std::fprintf(stderr, "opx-bench-world: bad argument '%s'\n", arg.c_str());
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
        std::printf("opx-bench-world: skipped: %s not found (set OPX_DATA_DIR to the shared data folder)\n",
                    missing.c_str());
        return 77;
    }
    const std::string cpu = paper_tables::cpu_name(), load = paper_tables::load_average();
    std::printf("opx-bench-world (OctoProx %s)\nCPU: %s\nload average at start: %s\n", opx_version(), cpu.c_str(),
                load.c_str());
    const RunResult result = run_all(options);
    batch_bench::print_rows(result.rows);
    std::printf("load average at end: %s\n", paper_tables::load_average().c_str());
    if (!json_path.empty() && !batch_bench::write_rows_json(json_path, result.rows, cpu, load)) {
        std::fprintf(stderr, "opx-bench-world: cannot write %s\n", json_path.c_str());
        return 1;
    }
    if (!result.composition_agrees)
        std::printf("FAIL: with the map and the objects, some answer is not the union of the two alone (MISMATCH above)\n");
    return result.composition_agrees ? 0 : 1;
}

}  // namespace
}  // namespace world_bench

int main(int argc, char **argv) {
    if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        world_bench::print_usage(stdout);
        return 0;
    }
    try {
        return world_bench::run(argc, argv);
    } catch (const std::exception &error) {
        std::fprintf(stderr, "opx-bench-world: %s\n", error.what());
        return 1;
    }
}
