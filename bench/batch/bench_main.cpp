#include "bench_main.hpp"

#include "machine_probe.hpp"
#include "pr2_scene.hpp"
#include "report.hpp"

#include <octoprox/octoprox.h>

#include <cstdlib>
#include <cstring>
#include <exception>

namespace batch_bench {
namespace {

bool parse_count(const char *text, long low, long high, long &out) {
    char *end = nullptr;
    out = std::strtol(text, &end, 10);
    return end != text && *end == '\0' && out >= low && out <= high;
}

bool parse_options(const BenchProgram &program, int argc, char **argv, BenchOptions &options,
                   std::string &json_path) {
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
        } else if (program.takes_rounds && arg == "--rounds" && has_value && parse_count(argv[++i], 1, 100, n)) {
            options.rounds = static_cast<int>(n);
        } else {
            std::fprintf(stderr, "%s: bad argument '%s'\n", program.name, arg.c_str());
            return false;
        }
    }
    if (options.quick) {
        if (!counted) options.configurations = 100;
        options.rounds = 1;
    }
    return true;
}

int run_program(const BenchProgram &program, int argc, char **argv, BenchOptions options,
                const std::function<BenchOutcome(const BenchOptions &)> &run) {
    std::string json_path;
    if (!parse_options(program, argc, argv, options, json_path)) {
        program.print_usage(stderr);
        return 2;
    }
    const std::string missing = paper_tables::missing_pr2_data();
    if (!missing.empty()) {
        std::printf("%s: skipped: %s not found (set OPX_DATA_DIR to the shared data folder)\n", program.name,
                    missing.c_str());
        return 77;
    }
    Machine machine;
    machine.cpu = paper_tables::cpu_name(), machine.load = paper_tables::load_average();
    machine.at_start = bench::measure_thread_speed();
    std::printf("%s (OctoProx %s)\nCPU: %s\nload average at start: %s\n", program.name, opx_version(),
                machine.cpu.c_str(), machine.load.c_str());
    const BenchOutcome outcome = run(options);
    print_rows(outcome.rows);
    machine.at_end = bench::measure_thread_speed();
    std::printf("load average at end: %s\n", paper_tables::load_average().c_str());
    bench::print_thread_speeds(machine.at_start, machine.at_end);
    if (!json_path.empty() && !write_rows_json(json_path, outcome.rows, machine)) {
        std::fprintf(stderr, "%s: cannot write %s\n", program.name, json_path.c_str());
        return 1;
    }
    if (!outcome.agree) std::printf("FAIL: %s\n", program.disagreement);
    return outcome.agree ? 0 : 1;
}

}  // namespace

int bench_main(const BenchProgram &program, int argc, char **argv, BenchOptions defaults,
               const std::function<BenchOutcome(const BenchOptions &)> &run) {
    if (argc > 1 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0)) {
        program.print_usage(stdout);
        return 0;
    }
    try {
        return run_program(program, argc, argv, defaults, run);
    } catch (const std::exception &error) {
        std::fprintf(stderr, "%s: %s\n", program.name, error.what());
        return 1;
    }
}

}  // namespace batch_bench
