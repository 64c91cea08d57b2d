#include "batch_run.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "certified_rows.hpp"
#include "pipelines.hpp"
#include "self_rows.hpp"
#include "sphere_rows.hpp"

namespace batch_bench {
namespace {

constexpr uint64_t kSeed = 0xBA7C4u;
constexpr size_t kMotions = 2000;
// Certified and 1/32-sampled motions per robot, map and thread count.
constexpr size_t kCertifiedMotions = 300;
// Self-distance calls timed per robot (each costs far more than a check).
constexpr size_t kSelfDistanceConfigurations = 500;
// Self-collision in the OctoProx pipelines (FCL always checks it).
constexpr bool kSelfCollision = true;

size_t count_of(const std::vector<uint8_t> &flags) { return size_t(std::count(flags.begin(), flags.end(), 1)); }

size_t differences(const std::vector<uint8_t> &a, const std::vector<uint8_t> &b) {
    size_t n = 0;
    for (size_t i = 0; i < a.size(); ++i) n += a[i] != b[i];
    return n;
}

// FCL always checks the robot against itself; OctoProx when kSelfCollision.
Row row(const Robot &robot, const Scene &scene, const char *pipeline, const Timing &t) {
    const bool self = kSelfCollision || std::string(pipeline) == "fcl";
    return Row{robot.name, scene.name, pipeline, t.us_per_configuration,
               {{"configurations", double(t.collided.size())}, {"collided", double(count_of(t.collided))},
                {"fastest_round_us", t.fastest_us}, {"self_collision", self ? 1.0 : 0.0}}};
}

Row motion_row(const Robot &robot, const Scene &scene, const char *pipeline, const MotionTiming &t) {
    return Row{robot.name, scene.name, pipeline, t.us_per_configuration,
               {{"motions", double(t.motions)}, {"collided", double(t.collided)},
                {"motions_per_second", t.motions_per_second},
                {"configurations_per_motion", t.configurations_per_motion},
                {"resolution_rad", kMotionResolution}, {"self_collision", kSelfCollision ? 1.0 : 0.0}}};
}

// "motion certified" and "motion sampled 1/32" for `threads`; false when
// a sampled check found a collision the certified one calls free.
bool certified_rows(const Workload &work, const std::vector<double> &goals, size_t count, uint32_t threads,
                    std::vector<Row> &rows) {
    const CertifiedTiming t = time_certified_motions(work, goals, count, threads);
    const double thread_count = double(threads);
    rows.push_back(Row{work.robot.name, work.scene.name, "motion certified", t.certified_us / t.certified_measured,
                       {{"us_per_motion", t.certified_us}, {"threads", thread_count}, {"motions", double(t.motions)},
                        {"collided", double(t.certified_collided)},
                        {"configurations_per_motion", t.certified_measured}, {"missed_by_sampling", 0.0},
                        {"self_collision", kSelfCollision ? 1.0 : 0.0}}});
    rows.push_back(Row{work.robot.name, work.scene.name, "motion sampled 1/32", t.sampled_us / t.sampled_checked,
                       {{"us_per_motion", t.sampled_us}, {"threads", thread_count}, {"motions", double(t.motions)},
                        {"collided", double(t.sampled_collided)}, {"configurations_per_motion", t.sampled_checked},
                        {"missed_by_sampling", double(t.missed_32)}, {"missed_by_sampling_1_16", double(t.missed_16)},
                        {"self_collision", kSelfCollision ? 1.0 : 0.0}}});
    std::printf("  %s, %s, %u thread(s): certified %.1f us a motion, sampled at 1/32 %.1f us (x%.2f); of %zu "
                "motions sampling calls free %zu (1/32) and %zu (1/16) the certified check finds colliding%s\n",
                work.robot.name.c_str(), work.scene.name.c_str(), threads, t.certified_us, t.sampled_us,
                t.certified_us / t.sampled_us, t.motions, t.missed_32, t.missed_16,
                t.unsound == 0 ? "" : "; MISMATCH: a sampled collision the certified check calls free");
    std::fflush(stdout);
    return t.unsound == 0;
}

bool check_agreement(const Robot &robot, const Scene &scene, const Timing &single, const Timing &one,
                     const Timing &two, const Timing &fcl) {
    const size_t bad = differences(single.collided, one.collided) + differences(single.collided, two.collided);
    std::printf("  %s, %s: %zu of %zu collide; batch vs single calls: %s; FCL (world + self) says %zu collide, "
                "%zu configurations differ from OctoProx%s\n",
                robot.name.c_str(), scene.name.c_str(), count_of(single.collided), single.collided.size(),
                bad == 0 ? "the same answers" : "MISMATCH", count_of(fcl.collided),
                differences(fcl.collided, one.collided), kSelfCollision ? "" : " (world only)");
    std::fflush(stdout);
    return bad == 0;
}

// The robot against itself alone: map "robot alone".
void self_rows(Robot &robot, const ConfigurationSet &set, FclCheck &fcl, const RunOptions &options,
               std::vector<Row> &rows) {
    const SelfTiming t =
        time_self_calls(robot, set, fcl, options.quick ? size_t(20) : kSelfDistanceConfigurations, options.rounds);
    const char *alone = "robot alone";
    rows.push_back(Row{robot.name, alone, "self collide call", t.collide_us,
                       {{"configurations", double(t.configurations)}, {"collided", double(t.collided)}}});
    rows.push_back(Row{robot.name, alone, "self distance call", t.distance_us,
                       {{"configurations", double(t.distance_configurations)}}});
    rows.push_back(Row{robot.name, alone, "fcl self collide", t.fcl_collide_us,
                       {{"configurations", double(t.configurations)}, {"collided", double(t.fcl_collided)}}});
    std::printf("  %s alone: %zu of %zu collide with themselves; FCL says %zu, %zu configurations differ\n",
                robot.name.c_str(), t.collided, t.configurations, t.fcl_collided, t.differ);
    std::fflush(stdout);
}

bool run_robot(Robot &robot, const Scene &scene, const opx_pose &base, const RunOptions &options,
               bool with_self_rows, std::vector<Row> &rows) {
    const ConfigurationSet set = draw_configurations(robot, base, options.configurations, kSeed, true);
    const Workload work{robot, scene, set, kSelfCollision, options.rounds};
    FclCheck fcl_check(robot, *scene.fcl_octree);
    const std::vector<Timing> t = time_interleaved(
        work, {single_calls(work), batch_call(work, 1), batch_call(work, 2), fcl_calls(work, fcl_check)});
    const Timing &single = t[0], &one = t[1], &two = t[2], &fcl = t[3];
    rows.push_back(row(robot, scene, "single calls", single));
    rows.push_back(row(robot, scene, "batch 1 thread", one));
    rows.push_back(row(robot, scene, "batch 2 threads", two));
    rows.push_back(row(robot, scene, "fcl", fcl));
    const std::vector<double> goals = motion_goals(set);
    const size_t motions = std::min(set.count, options.quick ? size_t(20) : kMotions);
    rows.push_back(motion_row(robot, scene, "motions batch 1 thread", time_motions(work, goals, motions, 1)));
    rows.push_back(motion_row(robot, scene, "motions batch 2 threads", time_motions(work, goals, motions, 2)));
    const size_t certified = std::min(set.count, options.quick ? size_t(10) : kCertifiedMotions);
    bool sound = certified_rows(work, goals, certified, 1, rows);
    sound &= certified_rows(work, goals, certified, 2, rows);
    if (with_self_rows) self_rows(robot, set, fcl_check, options, rows);
    return check_agreement(robot, scene, single, one, two, fcl) && sound;
}

void sphere_rows(Robot &arm, const Scene &scene, const RunOptions &options, std::vector<Row> &rows) {
    const SphereArmTiming a = time_sphere_arm(arm, scene, options.configurations, options.rounds);
    rows.push_back(Row{arm.name, scene.name, "batch 1 thread", a.us_per_configuration,
                       {{"ns_per_sphere", a.ns_per_sphere}, {"first_call_us", a.first_call_us},
                        {"configurations", double(a.configurations)},
                        {"collided", double(a.collided)}}});
    const SphereCallTiming s = time_single_sphere_calls(scene, options.configurations, options.rounds, false);
    rows.push_back(Row{"sphere", scene.name, "single sphere call", s.ns_per_call / 1000.0,
                       {{"ns_per_call", s.ns_per_call}, {"first_call_us", s.first_call_us}, {"calls", double(s.calls)},
                        {"collided", double(s.collided)}}});
    const SphereCallTiming l = time_single_sphere_calls(scene, options.configurations, options.rounds, true);
    rows.push_back(Row{"sphere", scene.name, "single sphere link set call", l.ns_per_call / 1000.0,
                       {{"ns_per_call", l.ns_per_call}, {"first_call_us", l.first_call_us}, {"calls", double(l.calls)},
                        {"collided", double(l.collided)}}});
    if (s.collided != l.collided) {
        std::fprintf(stderr, "opx-bench-batch: single spheres: %zu collided through opx_query_collide_spheres, %zu "
                             "through a link set\n", s.collided, l.collided);
        std::exit(1);
    }
}

void print_scene(const Scene &scene) {
    std::printf("map %s: %zu occupied cells; PR2 root at (%.2f, %.2f, %.3f), arms at its right shoulder\n",
                scene.name.c_str(), scene.occupied, scene.robot_base.position[0], scene.robot_base.position[1],
                scene.robot_base.position[2]);
    std::fflush(stdout);
}

}  // namespace

RunResult run_all(const RunOptions &options) {
    RunResult result;
    Robot pr2 = load_pr2(), arm = load_primitive_arm(), spheres = load_sphere_arm();
    std::printf("robots: PR2 (%zu joints, %zu shapes, %zu SRDF pairs disabled), arm 7 (%zu shapes), sphere arm 50; "
                "%zu configurations each; OctoProx self-collision %s\n",
                pr2.joints, pr2.shapes, pr2.disabled.size(), arm.shapes, options.configurations,
                kSelfCollision ? "on" : "off");
    for (int which = 0; which < 2; ++which) {
        const Scene scene = which == 0 ? real_scene(pr2.links.get()) : room_scene(pr2.links.get());
        print_scene(scene);
        result.agree &= run_robot(pr2, scene, scene.robot_base, options, which == 0, result.rows);
        result.agree &= run_robot(arm, scene, scene.arm_base, options, which == 0, result.rows);
        if (which == 0) sphere_rows(spheres, scene, options, result.rows);
    }
    return result;
}

}  // namespace batch_bench
