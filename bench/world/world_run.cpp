#include "world_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "world_pipelines.hpp"

namespace world_bench {
namespace {

constexpr uint64_t kConfigurationSeed = 0xB0A7D5u;
constexpr uint64_t kObjectSeed = 0x0B1EC7u;
const char *const kMap = "real frame 2 cm";
// The pipelines of a group, in the order of their timings.
enum { kObjects, kMapAlone, kBoth, kFcl, kBatch1, kBatch2 };

size_t count_of(const std::vector<uint8_t> &flags) { return size_t(std::count(flags.begin(), flags.end(), 1)); }

// FCL's answers against OctoProx's on the same objects: how many
// configurations differ, and how far OctoProx finds the robot from the
// objects at the worst of them (a difference at touching is a matter of
// the two libraries' tolerances, one far from it is not).
struct Disagreement {
    size_t count = 0;
    double largest_distance_m = 0.0;
};

Disagreement compare_fcl(Robot &robot, const ObjectSet &set, const Timing &opx, const Timing &fcl) {
    Disagreement d;
    for (size_t i = 0; i < opx.collided.size(); ++i) {
        if (opx.collided[i] == fcl.collided[i]) continue;
        ++d.count;
        const double distance = object_distance(robot, i, set.world.get());
        d.largest_distance_m = std::max(d.largest_distance_m, std::fabs(distance));
        std::printf("    configuration %zu: octoprox says %s, FCL %s; octoprox signed distance %.3g mm\n", i,
                    opx.collided[i] ? "collides" : "free", fcl.collided[i] ? "collides" : "free", 1000.0 * distance);
    }
    return d;
}

// Configurations where "map and objects" is not "map" or "objects", or
// where a batch call answers otherwise than the single calls.
size_t composition_mismatches(const std::vector<Timing> &t) {
    const Timing &objects = t[kObjects], &map = t[kMapAlone], &both = t[kBoth];
    size_t bad = 0;
    for (size_t i = 0; i < both.collided.size(); ++i)
        bad += both.collided[i] != (objects.collided[i] | map.collided[i]) ||
               t[kBatch1].collided[i] != both.collided[i] || t[kBatch2].collided[i] != both.collided[i];
    return bad;
}

// The map column names what the robot is checked against; single-call
// pipelines time forward kinematics apart (pose_update_us), a batch call
// holds it in its time.
batch_bench::Row opx_row(const std::string &map, size_t objects, const char *pipeline, const Timing &t) {
    batch_bench::Row row{"PR2", map, pipeline, t.query_us,
                         {{"objects", double(objects)}, {"configurations", double(t.collided.size())},
                          {"collided", double(count_of(t.collided))}, {"fastest_round_us", t.fastest_query_us}}};
    if (t.pose_us > 0.0) row.fields.insert(row.fields.begin() + 1, {"pose_update_us", t.pose_us});
    return row;
}

batch_bench::Row fcl_row(const std::string &map, size_t objects, const Timing &t, const Disagreement &d) {
    return batch_bench::Row{"PR2", map, "fcl", t.query_us,
                            {{"objects", double(objects)}, {"pose_update_us", t.pose_us},
                             {"configurations", double(t.collided.size())}, {"collided", double(count_of(t.collided))},
                             {"fastest_round_us", t.fastest_query_us}, {"differ_from_octoprox", double(d.count)},
                             {"largest_differing_distance_mm", 1000.0 * d.largest_distance_m}}};
}

double ratio(double a, double b) { return b > 0.0 ? a / b : 0.0; }

void print_group(const ObjectSet &set, const std::vector<Timing> &t, const Disagreement &d, size_t bad) {
    const size_t n = t[kObjects].collided.size();
    std::printf("  %s: collide with the objects %zu, the map %zu, both %zu of %zu; map + objects = map or objects, "
                "batch = single calls: %s\n",
                describe(set).c_str(), count_of(t[kObjects].collided), count_of(t[kMapAlone].collided),
                count_of(t[kBoth].collided), n, bad == 0 ? "on every configuration" : "MISMATCH");
    std::printf("    query us: objects %.2f, map %.2f, both %.2f, FCL objects %.2f (FCL / octoprox %.1fx); "
                "pose update us: octoprox FK %.2f, FCL placing %.2f; both in a batch call (FK inside): "
                "%.2f on 1 thread, %.2f on 2\n",
                t[kObjects].query_us, t[kMapAlone].query_us, t[kBoth].query_us, t[kFcl].query_us,
                ratio(t[kFcl].query_us, t[kObjects].query_us), t[kObjects].pose_us, t[kFcl].pose_us,
                t[kBatch1].query_us, t[kBatch2].query_us);
    std::printf("    FCL: %zu collide, %zu configurations differ from octoprox (largest |distance| there %.3g mm)\n",
                count_of(t[kFcl].collided), d.count, 1000.0 * d.largest_distance_m);
    std::fflush(stdout);
}

bool run_group(Robot &robot, const opx_octree *map, size_t count, const RunOptions &options,
               std::vector<batch_bench::Row> &rows) {
    const ObjectSet set = draw_objects(robot, count, kObjectSeed);
    const opx_world *world = set.world.get();
    std::vector<Timing> t;
    {
        const std::vector<Pipeline> pipelines{opx_pipeline(robot, nullptr, world), opx_pipeline(robot, map, nullptr),
                                              opx_pipeline(robot, map, world), fcl_pipeline(robot, *set.fcl.manager),
                                              opx_batch_pipeline(robot, map, world, 1),
                                              opx_batch_pipeline(robot, map, world, 2)};
        t = time_interleaved(robot.configurations.size(), options.rounds, pipelines);
    }
    const Disagreement d = compare_fcl(robot, set, t[kObjects], t[kFcl]);
    const size_t bad = composition_mismatches(t);
    print_group(set, t, d, bad);
    const std::string objects = std::to_string(count) + " objects", both = objects + " + " + kMap;
    rows.push_back(opx_row(objects, count, "octoprox direct", t[kObjects]));
    rows.push_back(opx_row(kMap, 0, "octoprox direct", t[kMapAlone]));
    rows.push_back(opx_row(both, count, "octoprox direct", t[kBoth]));
    rows.push_back(opx_row(both, count, "octoprox batch 1 thread", t[kBatch1]));
    rows.push_back(opx_row(both, count, "octoprox batch 2 threads", t[kBatch2]));
    rows.push_back(fcl_row(objects, count, t[kFcl], d));
    return bad == 0;
}

}  // namespace

RunResult run_all(const RunOptions &options) {
    RunResult result;
    Robot robot = load_robot(options.configurations, kConfigurationSeed);
    std::printf("robot: PR2 (%zu links, %zu of them moving), %zu reaching configurations; the arms reach the box "
                "x %.2f..%.2f, y %.2f..%.2f, z %.2f..%.2f m (10 objects to a box of its size, at its height)\n",
                robot.moving.size(), size_t(std::count(robot.moving.begin(), robot.moving.end(), 1)),
                robot.configurations.size(), robot.reach_min[0], robot.reach_max[0], robot.reach_min[1],
                robot.reach_max[1], robot.reach_min[2], robot.reach_max[2]);
    const paper_tables::OpxOctreePtr map = real_map(robot);
    std::fflush(stdout);
    for (size_t count : options.object_counts)
        result.composition_agrees &= run_group(robot, map.get(), count, options, result.rows);
    return result;
}

}  // namespace world_bench
