// opx-bench-plan: planning time with OctoProx's checker against FCL's over
// the same octree, the way MoveIt checks against an OctoMap.  RRTConnect
// solves random valid start and goal pairs of the PR2's right arm (the
// rest of the PR2 still, checked too) and of the 7-joint arm, in the real
// RGB-D frame and the generated room at 2 cm; each query twice with the
// same seeded samples, once per checker, interleaved.  Both check the map
// and the robot against itself; motions on the same grid (0.01 rad).
//   opx-bench-plan [--queries N] [--budget SECONDS] [--seed N] [--json FILE] [--quick]
#include "plan_run.hpp"
#include "pr2_scene.hpp"
#include "report.hpp"

#include <ompl/util/Console.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace plan_bench {
namespace {

struct Options {
    PlanOptions plan;
    std::string json;
};

int usage(FILE *out, int status) {
    std::fprintf(out,
                 "usage: opx-bench-plan [--queries N] [--budget SECONDS] [--seed N] [--json FILE] [--quick]\n"
                 "  --queries N        start and goal pairs per robot and map (default 100)\n"
                 "  --budget SECONDS   a plan's time limit; a plan not found by then fails (default 10)\n"
                 "  --seed N           the queries' and the planner's seed (default 1)\n"
                 "  --json FILE        also write the rows as a JSON list\n"
                 "  --quick            smoke run: 2 queries, 2 s budget\n"
                 "Needs the PR2 and the RGB-D frame of the shared data ($OPX_DATA_DIR, else ../shared/data);\n"
                 "exits 77 without them.\n");
    return status;
}

int parse(int argc, char **argv, Options &o) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help") return usage(stdout, 0) - 1;
        if (arg == "--quick") {
            o.plan.queries = 2, o.plan.budget = 2.0;
            continue;
        }
        if (i + 1 >= argc) return usage(stderr, 2);
        const char *value = argv[++i];
        if (arg == "--queries") o.plan.queries = std::strtoul(value, nullptr, 10);
        else if (arg == "--budget") o.plan.budget = std::atof(value);
        else if (arg == "--seed") o.plan.seed = std::strtoull(value, nullptr, 10);
        else if (arg == "--json") o.json = value;
        else return usage(stderr, 2);
    }
    if (o.plan.queries == 0 || !(o.plan.budget > 0.0)) return usage(stderr, 2);
    return 0;
}

void print_row(const PlanRow &r) {
    std::printf("%-10s %-9s %-14s %-20s %8.1f %8.1f %7zu/%-4zu %10.0f\n", r.planner.c_str(), r.checker.c_str(),
                r.robot.c_str(), r.map.c_str(), r.median_ms, r.p95_ms, r.solved, r.queries, r.configurations_per_s);
}

void write_json(const std::string &path, const std::vector<PlanRow> &rows, const std::vector<size_t> &same) {
    FILE *out = std::fopen(path.c_str(), "w");
    if (out == nullptr) {
        std::fprintf(stderr, "opx-bench-plan: cannot write %s\n", path.c_str());
        return;
    }
    std::fprintf(out, "[\n");
    for (size_t i = 0; i < rows.size(); ++i) {
        const PlanRow &r = rows[i];
        std::fprintf(out,
                     "  {\"planner\": \"%s\", \"checker\": \"%s\", \"robot\": \"%s\", \"map\": \"%s\", "
                     "\"queries\": %zu, \"median_ms\": %.3f, \"p95_ms\": %.3f, \"success\": %.4f, "
                     "\"configurations_checked\": %llu, \"configurations_per_s\": %.1f, "
                     "\"queries_with_the_same_steps\": %zu, \"cpu\": \"%s\"}%s\n",
                     r.planner.c_str(), r.checker.c_str(), r.robot.c_str(), r.map.c_str(), r.queries, r.median_ms,
                     r.p95_ms, static_cast<double>(r.solved) / static_cast<double>(r.queries),
                     (unsigned long long)r.configurations, r.configurations_per_s, same[i / 2],
                     paper_tables::cpu_name().c_str(), i + 1 < rows.size() ? "," : "");
    }
    std::fprintf(out, "]\n");
    std::fclose(out);
}

}  // namespace
}  // namespace plan_bench

int main(int argc, char **argv) {
    using namespace plan_bench;
    Options o;
    if (const int status = parse(argc, argv, o)) return status < 0 ? 0 : status;
    const std::string missing = paper_tables::missing_pr2_data();
    if (!missing.empty()) {
        std::fprintf(stderr, "opx-bench-plan: %s not found (set OPX_DATA_DIR); skipped\n", missing.c_str());
        return 77;
    }
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    batch_bench::Robot pr2 = batch_bench::load_pr2(), arm = batch_bench::load_primitive_arm();
    std::vector<batch_bench::Scene> scenes;
    scenes.push_back(batch_bench::real_scene(pr2.links.get()));
    scenes.push_back(batch_bench::room_scene(pr2.links.get()));
    std::printf("opx-bench-plan: RRTConnect, %zu queries per robot and map, %g s budget, seed %llu, CPU %s\n",
                o.plan.queries, o.plan.budget, (unsigned long long)o.plan.seed, paper_tables::cpu_name().c_str());
    std::printf("%-10s %-9s %-14s %-20s %8s %8s %12s %10s\n", "planner", "checker", "robot", "map", "med ms", "p95 ms",
                "solved", "configs/s");
    std::vector<PlanRow> rows;
    std::vector<size_t> same;
    for (batch_bench::Scene &scene : scenes) {
        const PairResult runs[2] = {
            run_pair(pr2, "PR2 right arm", scene, scene.robot_base, pr2_right_arm(pr2.links.get()), o.plan),
            run_pair(arm, "arm 7", scene, scene.arm_base, all_moving_joints(arm.links.get()), o.plan)};
        for (const PairResult &r : runs) {
            print_row(r.octoprox);
            print_row(r.fcl);
            std::printf("%-10s speed-up (median) %.1fx; the same steps in %zu of %zu queries\n", "",
                        r.fcl.median_ms / r.octoprox.median_ms, r.same_steps, r.octoprox.queries);
            rows.push_back(r.octoprox);
            rows.push_back(r.fcl);
            same.push_back(r.same_steps);
            same.push_back(r.same_steps);
        }
    }
    if (!o.json.empty()) write_json(o.json, rows, same);
    return 0;
}
