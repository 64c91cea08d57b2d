// opx-ompl-plan: OMPL's RRTConnect plans the PR2's right arm through the
// shared real RGB-D frame (a 2 cm map), known world objects and the
// robot itself, with OctoProx as its state validity checker and motion
// validator (octoprox_ompl.hpp); the path is simplified, printed, and
// checked again densely by other calls (dense_check.hpp).
//
//   opx-ompl-plan [--data DIR] [--budget SECONDS] [--seed N] [--resolution M] [--certified]
//
// Exit status: 0 planned and checked; 1 no plan within the budget or the
// dense check found a collision; 2 usage; 77 the shared data is absent.
#include "dense_check.hpp"
#include "pr2_scene.hpp"

#include <ompl/base/goals/GoalState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/config.h>
#include <ompl/geometric/SimpleSetup.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

namespace ob = ompl::base;
namespace og = ompl::geometric;

namespace {

#ifndef OPX_DEFAULT_DATA_DIR
#define OPX_DEFAULT_DATA_DIR "../shared/data"
#endif

// pr2.srdf's "tuck_right_arm", and the arm reaching forward over the table.
const double kStart[opx_ompl::kArmJoints] = {-0.023593, 1.10728, -1.55669, -2.12441, -1.4175, -1.8417, 0.21436};
const double kGoal[opx_ompl::kArmJoints] = {-0.1, 0.1, 0.0, -0.35, 0.0, -0.4, 0.0};

struct Options {
    std::string data_dir;
    double budget = 5.0;       // seconds for planning (simplifying gets at most as much)
    unsigned long seed = 1;
    double resolution = 0.02;  // the map's, metres
    bool certified = false;    // motions checked whole, not sampled
};

int usage(const char *why) {
    std::fprintf(stderr, "opx-ompl-plan: %s\nusage: opx-ompl-plan [--data DIR] [--budget SECONDS] [--seed N] "
                         "[--resolution METRES] [--certified]\n", why);
    return 2;
}

int parse(int argc, char **argv, Options &o) {
    const char *env = std::getenv("OPX_DATA_DIR");
    o.data_dir = env != nullptr && *env != '\0' ? env : OPX_DEFAULT_DATA_DIR;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (arg == "--help") return usage("plans the PR2's right arm with OMPL over OctoProx");
        if (arg == "--certified") {
            o.certified = true;
            continue;
        }
        if (i + 1 >= argc) return usage(("missing value after " + arg).c_str());
        const char *value = argv[++i];
        if (arg == "--data") o.data_dir = value;
        else if (arg == "--budget") o.budget = std::atof(value);
        else if (arg == "--seed") o.seed = std::strtoul(value, nullptr, 10);
        else if (arg == "--resolution") o.resolution = std::atof(value);
        else return usage(("unknown option " + arg).c_str());
    }
    if (!(o.budget > 0.0) || !(o.resolution > 0.0)) return usage("--budget and --resolution must be positive");
    return 0;
}

std::vector<std::vector<double>> waypoints_of(og::PathGeometric &path) {
    std::vector<std::vector<double>> rows;
    for (const ob::State *state : path.getStates()) {
        const double *v = state->as<ob::RealVectorStateSpace::StateType>()->values;
        rows.emplace_back(v, v + opx_ompl::kArmJoints);
    }
    return rows;
}

void print_path(const std::vector<std::vector<double>> &rows) {
    std::printf("path (rad):");
    for (const char *name : opx_ompl::kArmJointNames) std::printf(" %s", name);
    std::printf("\n");
    for (size_t w = 0; w < rows.size(); ++w) {
        std::printf("  %2zu:", w);
        for (double v : rows[w]) std::printf(" %7.3f", v);
        std::printf("\n");
    }
}

og::SimpleSetup make_setup(const opx_ompl::Pr2Scene &scene, std::shared_ptr<opx_ompl::CheckCounts> counts) {
    auto space = std::make_shared<ob::RealVectorStateSpace>(opx_ompl::kArmJoints);
    ob::RealVectorBounds bounds(opx_ompl::kArmJoints);
    for (size_t j = 0; j < opx_ompl::kArmJoints; ++j) {
        bounds.setLow(j, scene.lower[j]);
        bounds.setHigh(j, scene.upper[j]);
    }
    space->setBounds(bounds);
    og::SimpleSetup setup(space);
    const ob::SpaceInformationPtr &si = setup.getSpaceInformation();
    setup.setStateValidityChecker(std::make_shared<opx_ompl::StateValidityChecker>(si, scene.check, counts));
    si->setMotionValidator(std::make_shared<opx_ompl::MotionValidator>(si, scene.check, counts));
    setup.setPlanner(std::make_shared<og::RRTConnect>(si));
    ob::ScopedState<> start(space), goal(space);
    for (size_t j = 0; j < opx_ompl::kArmJoints; ++j) {
        start[j] = kStart[j];
        goal[j] = kGoal[j];
    }
    setup.setStartAndGoalStates(start, goal);
    return setup;
}

int report_dense(const opx_ompl::CheckScene &check, const std::vector<std::vector<double>> &rows) {
    const double step = check.resolution / 5.0;
    const auto t0 = std::chrono::steady_clock::now();
    const opx_ompl::DenseCheckResult dense = opx_ompl::dense_check(check, rows, step, true);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("dense check of the unpadded arm: %llu configurations %.4f rad apart, one call each (FK, map and "
                "objects, self): "
                "%llu colliding, %llu self-colliding, %.0f ms\n",
                (unsigned long long)dense.configurations, step, (unsigned long long)dense.colliding,
                (unsigned long long)dense.self_colliding, ms);
    if (dense.colliding + dense.self_colliding == 0) return 0;
    std::printf("FAILED: the path collides at waypoint %.3f\n", dense.first_collision_at);
    return 1;
}

// A start or goal in collision has no plan: say what touches what.
bool ends_are_free(og::SimpleSetup &setup, const opx_ompl::Pr2Scene &scene) {
    const ob::ProblemDefinitionPtr &problem = setup.getProblemDefinition();
    const ob::State *goal = problem->getGoal()->as<ob::GoalState>()->getState();
    const ob::SpaceInformationPtr &si = setup.getSpaceInformation();
    if (si->isValid(problem->getStartState(0)) && si->isValid(goal)) return true;
    opx_ompl::explain_collisions(scene.check, std::vector<double>(kStart, kStart + opx_ompl::kArmJoints), "start");
    opx_ompl::explain_collisions(scene.check, std::vector<double>(kGoal, kGoal + opx_ompl::kArmJoints), "goal");
    std::printf("FAILED: the start or the goal collides\n");
    return false;
}

// What planning checked, before simplifying adds its own checks.
struct PlanFigures {
    double ms = 0.0;
    uint64_t states = 0, motion_configurations = 0, motions = 0;
    size_t waypoints = 0;
};

void print_plan(const Options &o, og::SimpleSetup &setup, const opx_ompl::CheckScene &check, const PlanFigures &f,
                const opx_ompl::CheckCounts &counts, const std::vector<std::vector<double>> &rows) {
    if (check.certified)
        std::printf("planner: RRTConnect, seed %lu, motions certified (checked whole)\n", o.seed);
    else
        std::printf("planner: RRTConnect, seed %lu, motions checked every %.3f rad\n", o.seed, check.resolution);
    std::printf("planning time: %.1f ms; %llu configurations checked (%llu states, %llu in %llu motions)\n", f.ms,
                (unsigned long long)(f.states + f.motion_configurations), (unsigned long long)f.states,
                (unsigned long long)f.motion_configurations, (unsigned long long)f.motions);
    std::printf("simplifying: %.1f ms, %zu waypoints to %zu, %llu configurations checked in all\n",
                setup.getLastSimplificationTime() * 1e3, f.waypoints, rows.size(), (unsigned long long)counts.total());
    print_path(rows);
}

}  // namespace

int main(int argc, char **argv) {
    Options o;
    if (const int status = parse(argc, argv, o)) return status;
    ompl::msg::setLogLevel(ompl::msg::LOG_WARN);
    ompl::RNG::setSeed(o.seed);
    opx_ompl::Pr2Scene scene;
    if (const int status = opx_ompl::load_pr2_scene(o.data_dir, o.resolution, scene)) return status;
    scene.check.certified = o.certified;
    std::printf("OctoProx %s with OMPL %d.%d.%d: the PR2's right arm, a real RGB-D frame at %g cm (%llu occupied "
                "cells), 2 world objects, self-collision with pr2.srdf\n",
                opx_version(), OMPL_MAJOR_VERSION, OMPL_MINOR_VERSION, OMPL_PATCH_VERSION, o.resolution * 100.0,
                (unsigned long long)scene.occupied_cells);
    auto counts = std::make_shared<opx_ompl::CheckCounts>();
    og::SimpleSetup setup = make_setup(scene, counts);
    if (!ends_are_free(setup, scene)) return 1;
    counts->states = 0;
    const ob::PlannerStatus solved = setup.solve(o.budget);
    if (solved != ob::PlannerStatus::EXACT_SOLUTION) {
        std::printf("FAILED: no plan within %g s (%s); %llu configurations checked\n", o.budget,
                    solved.asString().c_str(), (unsigned long long)counts->total());
        return 1;
    }
    const PlanFigures figures{setup.getLastPlanComputationTime() * 1e3, counts->states, counts->motion_configurations,
                              counts->motions, setup.getSolutionPath().getStateCount()};
    setup.simplifySolution(o.budget);
    const std::vector<std::vector<double>> rows = waypoints_of(setup.getSolutionPath());
    print_plan(o, setup, scene.check, figures, *counts, rows);
    return report_dense(scene.check, rows);
}
