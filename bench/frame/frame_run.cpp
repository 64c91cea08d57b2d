#include "frame_run.hpp"

#include <cmath>
#include <cstdio>

#include "fcl_distance.hpp"
#include "opx_distance.hpp"
#include "opx_pipelines.hpp"
#include "timing.hpp"

namespace frame_bench {
namespace {

using paper_tables::check_opx;
using paper_tables::Configuration;
using paper_tables::time_once_ms;

constexpr int kShown = 5;  // mismatches printed

// Everything a run keeps across its frames.
struct RunState {
    Stream &stream;
    Robot &robot;
    OpxMaps opx;
    OctomapMaps octomap;
    paper_tables::OpxQueryPtr direct = paper_tables::make_direct_query();
    paper_tables::OpxQueryPtr amortized = paper_tables::make_amortized_query();
    paper_tables::FclObjectPtr octree;  // the fcl::OcTree of this frame
    HeapBook engine_heap[kPipelineCount];
    std::vector<int> distance_set;      // configuration indices, chosen on frame 0
    RunState(Stream &s, Robot &r, double resolution) : stream(s), robot(r), opx(resolution), octomap(resolution) {}
};

// Times `work` into `ms` (added) and books its heap on the pipeline's engine.
template <class Work>
auto timed(RunState &state, Pipeline p, double &ms, Work &&work) {
    decltype(work()) answer{};
    state.engine_heap[p].add(measure_heap([&] { ms += time_once_ms([&] { answer = work(); }); }));
    return answer;
}

opx_linkset *robot_links(RunState &state, Pipeline p) {
    return p == kDirect ? state.robot.links : state.robot.links_amortized;
}

void move_robot(RunState &state, Pipeline p, const Configuration &c, StageTimes &times) {
    timed(state, p, times[kPoseUpdate], [&] {
        if (p == kFcl) {
            state.robot.fcl->set_link_poses(c.poses);
        } else {
            check_opx(opx_linkset_set_joint_positions(robot_links(state, p), c.joints.data(), c.joints.size(),
                                                      &state.robot.base),
                      "opx_linkset_set_joint_positions");
        }
        return 0;
    });
}

opx_query *engine(RunState &state, Pipeline p) { return p == kDirect ? state.direct.get() : state.amortized.get(); }


bool collide(RunState &state, Pipeline p, StageTimes &times) {
    return timed(state, p, times[kCollision], [&] {
        if (p == kFcl) return paper_tables::fcl_octree_collides(state.robot.fcl->manager(), *state.octree);
        return paper_tables::opx_collides(engine(state, p), state.opx.raycast(), robot_links(state, p));
    });
}

double distance(RunState &state, Pipeline p, StageTimes &times) {
    return timed(state, p, times[kDistance], [&] {
        if (p == kFcl) return paper_tables::fcl_octree_distance(state.robot.fcl->manager(), *state.octree);
        return paper_tables::opx_min_distance(engine(state, p), state.opx.raycast(), robot_links(state, p));
    });
}

void ingest(RunState &state, std::array<StageTimes, kPipelineCount> &times) {
    state.opx.ingest(state.stream.frame, times[kDirect]);
    times[kAmortized][kIngestRaycast] = times[kDirect][kIngestRaycast];
    times[kAmortized][kIngestEndpoints] = times[kDirect][kIngestEndpoints];
    state.octomap.ingest(state.stream.frame, times[kFcl]);
}

void build_structures(RunState &state, std::array<StageTimes, kPipelineCount> &times) {
    timed(state, kAmortized, times[kAmortized][kStructure],
          [&] { return paper_tables::opx_collides(state.amortized.get(), state.opx.raycast(), state.robot.links_amortized); });
    timed(state, kFcl, times[kFcl][kStructure], [&] {
        state.octree = paper_tables::wrap_octree(state.octomap.raycast());
        return 0;
    });
}

void note_collision_mismatch(int frame, size_t c, const bool answers[kPipelineCount], Checks &checks) {
    if (++checks.collision_mismatches > kShown) return;
    std::printf("  MISMATCH frame %d configuration %zu: collided direct %d, amortized %d, FCL %d\n", frame, c,
                answers[kDirect], answers[kAmortized], answers[kFcl]);
}

// The 1,000 collision queries; returns octoprox direct's answers.
std::vector<bool> run_collisions(RunState &state, int frame, std::array<StageTimes, kPipelineCount> &times,
                                 Checks &checks) {
    const std::vector<Configuration> &set = state.robot.configurations;
    std::vector<bool> direct_answers(set.size());
    for (size_t c = 0; c < set.size(); ++c) {
        bool answers[kPipelineCount];
        for (int k = 0; k < kPipelineCount; ++k) {
            const Pipeline p = static_cast<Pipeline>((c + frame + k) % kPipelineCount);
            move_robot(state, p, set[c], times[p]);
            answers[p] = collide(state, p, times[p]);
        }
        direct_answers[c] = answers[kDirect];
        checks.collided += answers[kDirect];
        ++checks.collision_compared;
        if (answers[kDirect] != answers[kAmortized] || answers[kDirect] != answers[kFcl])
            note_collision_mismatch(frame, c, answers, checks);
    }
    return direct_answers;
}

// The configurations' joint vectors, one row each, for the batch call.
std::vector<double> joint_rows(const std::vector<Configuration> &set) {
    std::vector<double> rows;
    for (const Configuration &c : set) rows.insert(rows.end(), c.joints.begin(), c.joints.end());
    return rows;
}

// The same configurations in one batch call per octoprox engine, on every
// core; its answers must be the single calls'.
std::array<double, kPipelineCount> run_batch(RunState &state, const std::vector<bool> &direct_answers, Checks &checks) {
    const std::vector<Configuration> &set = state.robot.configurations;
    const std::vector<double> rows = joint_rows(set);
    const size_t joints = set.empty() ? 0 : set[0].joints.size();
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.max_threads = 0;
    std::vector<uint8_t> collided(set.size());
    std::array<double, kPipelineCount> ms{};
    for (const Pipeline p : {kDirect, kAmortized}) {
        ms[p] = time_once_ms([&] {
            check_opx(opx_query_check_configurations(engine(state, p), state.opx.raycast(), robot_links(state, p),
                                                     rows.data(), set.size(), joints, 0, &state.robot.base, 1, 0,
                                                     &request, collided.data(), nullptr, collided.size()),
                      "opx_query_check_configurations");
        });
        for (size_t c = 0; c < set.size(); ++c) checks.batch_mismatches += (collided[c] != 0) != direct_answers[c];
    }
    return ms;
}

// The first `count` configurations that are collision-free in the first
// frame (a distance query there computes the full minimum), topped up with
// colliding ones when too few are free.
std::vector<int> choose_distance_set(const std::vector<bool> &collided, int count, Checks &checks) {
    std::vector<int> set;
    for (size_t c = 0; c < collided.size() && static_cast<int>(set.size()) < count; ++c)
        if (!collided[c]) set.push_back(static_cast<int>(c));
    checks.distance_free = static_cast<int>(set.size());
    for (size_t c = 0; c < collided.size() && static_cast<int>(set.size()) < count; ++c)
        if (collided[c]) set.push_back(static_cast<int>(c));
    return set;
}

void check_distances(const double d[kPipelineCount], bool fcl_measured, Checks &checks) {
    ++checks.distance_compared;
    checks.engines_distance_gap = std::max(checks.engines_distance_gap, std::fabs(d[kDirect] - d[kAmortized]));
    if (!fcl_measured) return;
    ++checks.fcl_distance_compared;
    const double gap = std::fabs(d[kDirect] - d[kFcl]);
    checks.fcl_distance_gap = std::max(checks.fcl_distance_gap, gap);
    checks.fcl_distance_off += gap > kDistanceTolerance;
}

// The distance queries.  FCL measures only the first fcl_distance_queries
// of them (its robot is still moved for all); its distance time is then
// scaled to the full count.
void run_distances(RunState &state, int frame, const RunPlan &plan, std::array<StageTimes, kPipelineCount> &times,
                   Checks &checks) {
    const int measured_by_fcl = std::min<int>(plan.fcl_distance_queries, state.distance_set.size());
    for (size_t i = 0; i < state.distance_set.size(); ++i) {
        const Configuration &c = state.robot.configurations[state.distance_set[i]];
        const bool fcl_measured = static_cast<int>(i) < measured_by_fcl;
        double d[kPipelineCount] = {0, 0, 0};
        for (int k = 0; k < kPipelineCount; ++k) {
            const Pipeline p = static_cast<Pipeline>((i + frame + k) % kPipelineCount);
            move_robot(state, p, c, times[p]);
            if (p != kFcl || fcl_measured) d[p] = distance(state, p, times[p]);
        }
        check_distances(d, fcl_measured, checks);
    }
    if (measured_by_fcl > 0)
        times[kFcl][kDistance] *= static_cast<double>(state.distance_set.size()) / measured_by_fcl;
}

void print_frame(const RunResult &result, int frame) {
    std::printf("  %s %.0f cm frame %d/%d:", result.stream.c_str(), result.plan.resolution * 100, frame + 1,
                result.plan.frames);
    for (int p = 0; p < kPipelineCount; ++p) {
        double total = 0.0;
        for (int s = 0; s < kStageCount; ++s) total += s == kIngestEndpoints ? 0.0 : result.frames.back()[p][s];
        std::printf(" %s %.1f ms;", kPipelineNames[p], total);
    }
    std::printf("\n");
    std::fflush(stdout);
}

void keep_memory(const RunState &state, RunResult &result) {
    result.opx_raycast = state.opx.raycast_memory();
    result.opx_endpoints = state.opx.endpoints_memory();
    result.octomap_raycast = state.octomap.raycast_memory();
    result.octomap_endpoints = state.octomap.endpoints_memory();
    for (int p = 0; p < kPipelineCount; ++p)
        result.heap_high[p] = (p == kFcl ? state.octomap.raycast_heap.high : state.opx.raycast_heap.high) +
                              state.engine_heap[p].high;
    result.opx_endpoints_heap_high = state.opx.endpoints_heap.high;
    result.octomap_endpoints_heap_high = state.octomap.endpoints_heap.high;
}

}  // namespace

bool Checks::ok() const {
    return collision_mismatches == 0 && batch_mismatches == 0 && engines_distance_gap <= kDistanceTolerance &&
           collision_compared > 0;
}

RunResult run_frames(Stream &stream, Robot &robot, const RunPlan &plan) {
    RunResult result;
    result.stream = stream.name;
    result.plan = plan;
    result.configurations = static_cast<int>(robot.configurations.size());
    RunState state(stream, robot, plan.resolution);
    for (int frame = 0; frame < plan.frames; ++frame) {
        move_sensor_to_frame(stream, frame);
        std::array<StageTimes, kPipelineCount> times{};
        ingest(state, times);
        build_structures(state, times);
        const std::vector<bool> collided = run_collisions(state, frame, times, result.checks);
        if (!state.robot.configurations.empty()) result.batch_ms.push_back(run_batch(state, collided, result.checks));
        if (frame == 0) state.distance_set = choose_distance_set(collided, plan.distance_queries, result.checks);
        run_distances(state, frame, plan, times, result.checks);
        result.frames.push_back(times);
        print_frame(result, frame);
    }
    keep_memory(state, result);
    return result;
}

}  // namespace frame_bench
