// opx-bench-batch: many configurations per call.  The PR2 and a 7-joint
// arm at random reachable configurations against the real 2 cm frame and
// the generated room: the one-call-per-configuration way, the batch call on
// 1 and 2 threads, and FCL (world + self-collision, its FK untimed), in
// microseconds per configuration; motion checks per second; certified
// motion checks against sampled ones at 1/32 rad (us per motion, and the
// collisions sampling misses); each robot
// against itself alone (self-collision and self-distance calls, and FCL's
// self-collision); and the sphere rows (a 50-sphere arm through the batch
// call, one sphere per call).
//   opx-bench-batch [--quick] [--json FILE] [--configurations N]
#include <cstdio>

#include "batch_run.hpp"
#include "bench_main.hpp"

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

}  // namespace
}  // namespace batch_bench

int main(int argc, char **argv) {
    const batch_bench::RunOptions defaults;
    const batch_bench::BenchProgram program{"opx-bench-batch", false, batch_bench::print_usage,
                                            "the batch call and the single calls disagree (see MISMATCH above)"};
    return batch_bench::bench_main(program, argc, argv, {defaults.quick, defaults.configurations, defaults.rounds},
                                   [](const batch_bench::BenchOptions &given) {
                                       batch_bench::RunOptions options;
                                       options.quick = given.quick, options.configurations = given.configurations,
                                       options.rounds = given.rounds;
                                       const batch_bench::RunResult result = batch_bench::run_all(options);
                                       return batch_bench::BenchOutcome{result.rows, result.agree};
                                   });
}
