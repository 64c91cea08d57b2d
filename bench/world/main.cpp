// opx-bench-world: the PR2 among known objects.  10,000 reaching
// configurations checked against 10, 100 and 1,000 random objects (boxes,
// cylinders, spheres, a tenth of them as meshes; the same 10 within the
// arms' reach, the others around them), the real 2 cm RGB-D frame, and both (octoprox, direct engine, forward
// kinematics and one opx_query_collide per configuration; batch calls),
// next to FCL's collision manager on the same objects.  Microseconds per
// configuration, pose updates and queries apart.
//   opx-bench-world [--quick] [--json FILE] [--configurations N] [--rounds N]
#include <cstdio>

#include "bench_main.hpp"
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

}  // namespace
}  // namespace world_bench

int main(int argc, char **argv) {
    const world_bench::RunOptions defaults;
    const batch_bench::BenchProgram program{
        "opx-bench-world", true, world_bench::print_usage,
        "with the map and the objects, some answer is not the union of the two alone (MISMATCH above)"};
    return batch_bench::bench_main(
        program, argc, argv, {defaults.quick, defaults.configurations, defaults.rounds},
        [&](const batch_bench::BenchOptions &given) {
            world_bench::RunOptions options = defaults;
            options.quick = given.quick, options.configurations = given.configurations, options.rounds = given.rounds;
            const world_bench::RunResult result = world_bench::run_all(options);
            return batch_bench::BenchOutcome{result.rows, result.composition_agrees};
        });
}
