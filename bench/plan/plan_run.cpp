#include "plan_run.hpp"

#include "plan_checkers.hpp"

#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace plan_bench {
namespace {

void require(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

struct Space {
    std::shared_ptr<ob::RealVectorStateSpace> space;
    std::vector<double> lower, upper;
};

Space make_space(const opx_linkset *robot, const std::vector<uint32_t> &planned) {
    Space s;
    s.space = std::make_shared<ob::RealVectorStateSpace>(planned.size());
    ob::RealVectorBounds bounds(planned.size());
    for (size_t d = 0; d < planned.size(); ++d) {
        opx_joint_info info = OPX_JOINT_INFO_INIT;
        require(opx_linkset_get_joint_info(robot, planned[d], &info), "opx_linkset_get_joint_info");
        const bool bounded = info.type != OPX_JOINT_CONTINUOUS && info.has_limits;
        s.lower.push_back(bounded ? info.lower : -M_PI);
        s.upper.push_back(bounded ? info.upper : M_PI);
        bounds.setLow(d, s.lower.back());
        bounds.setHigh(d, s.upper.back());
    }
    s.space->setBounds(bounds);
    return s;
}

// A checker's space information: its validity checker and motion validator.
struct Checker {
    ob::SpaceInformationPtr si;
    std::shared_ptr<opx_ompl::CheckCounts> counts = std::make_shared<opx_ompl::CheckCounts>();
};

using Query = std::pair<std::vector<double>, std::vector<double>>;

// Uniform draws within the bounds until both checkers call start and goal free.
std::vector<Query> draw_queries(const Space &s, opx_ompl::SceneQuery &opx, FclQuery &fcl, size_t count,
                                uint64_t seed) {
    std::mt19937_64 rng(seed);
    ob::ScopedState<> state(s.space);
    auto draw = [&](std::vector<double> &out) {
        for (size_t attempt = 0; attempt < 100000; ++attempt) {
            for (size_t d = 0; d < s.lower.size(); ++d)
                state[d] = std::uniform_real_distribution<double>(s.lower[d], s.upper[d])(rng);
            if (opx.valid(state.get()) && fcl.valid(state.get())) {
                out = state.reals();
                return;
            }
        }
        throw std::runtime_error("no free configuration in 100000 draws");
    };
    std::vector<Query> queries(count);
    for (Query &q : queries) draw(q.first), draw(q.second);
    return queries;
}

struct Outcome {
    double ms = 0.0;
    bool solved = false;
    uint64_t configurations = 0;
};

Outcome solve(Checker &checker, const Space &s, const Query &query, uint32_t seed, double budget) {
    s.space->setStateSamplerAllocator(
        [seed](const ob::StateSpace *space) { return std::make_shared<SeededSampler>(space, seed); });
    ob::ScopedState<> start(s.space), goal(s.space);
    for (size_t d = 0; d < s.lower.size(); ++d) start[d] = query.first[d], goal[d] = query.second[d];
    auto problem = std::make_shared<ob::ProblemDefinition>(checker.si);
    problem->setStartAndGoalStates(start, goal);
    og::RRTConnect planner(checker.si);
    planner.setProblemDefinition(problem);
    planner.setup();
    const uint64_t before = checker.counts->total();
    const auto t0 = std::chrono::steady_clock::now();
    const ob::PlannerStatus status = planner.solve(ob::timedPlannerTerminationCondition(budget));
    Outcome out;
    out.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    out.solved = status == ob::PlannerStatus::EXACT_SOLUTION;
    out.configurations = checker.counts->total() - before;
    return out;
}

double percentile(std::vector<double> values, double p) {
    std::sort(values.begin(), values.end());
    const size_t index = static_cast<size_t>(std::ceil(p * static_cast<double>(values.size()))) - 1;
    return values[std::min(index, values.size() - 1)];
}

PlanRow summarise(const std::string &checker, const std::string &robot, const std::string &map,
                  const std::vector<Outcome> &outcomes) {
    PlanRow row;
    row.checker = checker, row.robot = robot, row.map = map, row.queries = outcomes.size();
    std::vector<double> ms;
    double total_ms = 0.0;
    for (const Outcome &o : outcomes) {
        ms.push_back(o.ms);
        total_ms += o.ms;
        row.solved += o.solved;
        row.configurations += o.configurations;
    }
    row.median_ms = percentile(ms, 0.5);
    row.p95_ms = percentile(ms, 0.95);
    row.configurations_per_s = total_ms > 0.0 ? static_cast<double>(row.configurations) / (total_ms * 1e-3) : 0.0;
    return row;
}

}  // namespace

std::vector<uint32_t> pr2_right_arm(const opx_linkset *pr2) {
    static const char *const kNames[7] = {"r_shoulder_pan_joint", "r_shoulder_lift_joint", "r_upper_arm_roll_joint",
                                          "r_elbow_flex_joint",   "r_forearm_roll_joint",  "r_wrist_flex_joint",
                                          "r_wrist_roll_joint"};
    std::vector<uint32_t> joints(7);
    for (size_t j = 0; j < 7; ++j) require(opx_linkset_find_joint(pr2, kNames[j], &joints[j]), "opx_linkset_find_joint");
    return joints;
}

std::vector<uint32_t> all_moving_joints(const opx_linkset *robot) {
    size_t count = 0;
    opx_linkset_get_active_joints(robot, nullptr, 0, &count);  // BUFFER_TOO_SMALL gives the count
    std::vector<uint32_t> joints(count);
    require(opx_linkset_get_active_joints(robot, joints.data(), count, &count), "opx_linkset_get_active_joints");
    return joints;
}

namespace {

// The OctoProx side's scene: the map, the robot at `base`, its current
// joint positions but the planned ones, self-collision, 0.01 rad motions.
opx_ompl::CheckScene check_scene(batch_bench::Robot &robot, batch_bench::Scene &scene, const opx_pose &base,
                                 const std::vector<uint32_t> &planned) {
    opx_ompl::CheckScene check;
    check.map = scene.tree.get();
    check.robot = robot.links.get();
    check.base_pose = base;
    size_t joints = 0;
    opx_linkset_get_joint_positions(check.robot, nullptr, 0, &joints);  // BUFFER_TOO_SMALL gives the count
    check.joint_positions.resize(joints);
    require(opx_linkset_get_joint_positions(check.robot, check.joint_positions.data(), joints, &joints),
            "opx_linkset_get_joint_positions");
    check.planned_joints = planned;
    return check;
}

// Plans every query with both checkers, interleaved, the order alternating
// so that neither always runs on a warmer (or busier) machine.
PairResult plan_all(Checker &opx, Checker &fcl, const Space &s, const std::vector<Query> &queries,
                    const PlanOptions &options, const std::string &label) {
    std::vector<Outcome> opx_out, fcl_out;
    PairResult result;
    for (size_t q = 0; q < queries.size(); ++q) {
        const uint32_t seed = static_cast<uint32_t>(options.seed * 1000003u + q);
        if (q % 2 == 0) opx_out.push_back(solve(opx, s, queries[q], seed, options.budget));
        fcl_out.push_back(solve(fcl, s, queries[q], seed, options.budget));
        if (q % 2 == 1) opx_out.push_back(solve(opx, s, queries[q], seed, options.budget));
        result.same_steps += opx_out.back().configurations == fcl_out.back().configurations;
        std::fprintf(stderr, "\r%s: query %zu/%zu", label.c_str(), q + 1, queries.size());
    }
    std::fprintf(stderr, "\n");
    result.octoprox = summarise("octoprox", "", "", opx_out);
    result.fcl = summarise("fcl", "", "", fcl_out);
    return result;
}

}  // namespace

PairResult run_pair(batch_bench::Robot &robot, const std::string &robot_name, batch_bench::Scene &scene,
                    const opx_pose &base, const std::vector<uint32_t> &planned, const PlanOptions &options) {
    const opx_ompl::CheckScene check = check_scene(robot, scene, base, planned);
    const Space s = make_space(check.robot, planned);
    Checker opx{std::make_shared<ob::SpaceInformation>(s.space)}, fcl{std::make_shared<ob::SpaceInformation>(s.space)};
    auto fcl_query = std::make_shared<FclQuery>(robot, *scene.fcl_octree, check);
    opx.si->setStateValidityChecker(std::make_shared<opx_ompl::StateValidityChecker>(opx.si, check, opx.counts));
    opx.si->setMotionValidator(std::make_shared<opx_ompl::MotionValidator>(opx.si, check, opx.counts));
    fcl.si->setStateValidityChecker(std::make_shared<FclValidityChecker>(fcl.si, fcl_query, fcl.counts));
    fcl.si->setMotionValidator(std::make_shared<FclMotionValidator>(fcl.si, fcl_query, fcl.counts));
    opx.si->setup();
    fcl.si->setup();
    opx_ompl::SceneQuery draw_query(check);
    const std::vector<Query> queries = draw_queries(s, draw_query, *fcl_query, options.queries, options.seed);
    PairResult result = plan_all(opx, fcl, s, queries, options, robot_name + ", " + scene.name);
    for (PlanRow *row : {&result.octoprox, &result.fcl}) row->robot = robot_name, row->map = scene.name;
    return result;
}

}  // namespace plan_bench
