// The FCL side of opx-bench-plan, as MoveIt checks against an OctoMap
// today: forward kinematics on a copy of the link set, the robot's FCL
// objects moved to the link poses, then FCL against the map as an
// fcl::OcTree and the robot against itself (batch_bench::FclCheck: the
// SRDF's pairs, or the arm's adjacent links, skipped). Motions are checked
// on the same grid, in the same order, as opx_query_check_motion checks
// them (every joint at most `resolution` apart; the ends, then ever finer
// midpoints; the first collision ends the check), so both checkers answer
// the same questions and, with the same seed, the planner takes the same
// steps.  And a state sampler seeded per query, so that each query's
// planner draws the same samples under either checker.
#pragma once

#include "fcl_check.hpp"
#include "octoprox_ompl.hpp"

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/samplers/UniformValidStateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace plan_bench {

// The FCL counterpart of opx_ompl::SceneQuery.
class FclQuery {
public:
    FclQuery(batch_bench::Robot &robot, fcl::CollisionObjectd &octree, const opx_ompl::CheckScene &scene);
    ~FclQuery();
    bool valid(const ompl::base::State *state);
    // As opx_query_check_motion: true when free; else *out_fraction.
    bool motion(const ompl::base::State *a, const ompl::base::State *b, double *out_fraction, uint64_t *out_steps,
                uint64_t *out_checked);

private:
    bool free_at(const std::vector<double> &row);

    const opx_ompl::CheckScene &scene_;
    batch_bench::FclCheck check_;
    opx_linkset *copy_ = nullptr;
    std::vector<double> row_, a_, b_;
};

class FclValidityChecker : public ompl::base::StateValidityChecker {
public:
    FclValidityChecker(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<FclQuery> query,
                       std::shared_ptr<opx_ompl::CheckCounts> counts)
        : ompl::base::StateValidityChecker(si), query_(std::move(query)), counts_(std::move(counts)) {}
    bool isValid(const ompl::base::State *state) const override;

private:
    std::shared_ptr<FclQuery> query_;
    std::shared_ptr<opx_ompl::CheckCounts> counts_;
};

class FclMotionValidator : public ompl::base::MotionValidator {
public:
    FclMotionValidator(const ompl::base::SpaceInformationPtr &si, std::shared_ptr<FclQuery> query,
                       std::shared_ptr<opx_ompl::CheckCounts> counts)
        : ompl::base::MotionValidator(si), query_(std::move(query)), counts_(std::move(counts)) {}
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                     std::pair<ompl::base::State *, double> &last_valid) const override;

private:
    std::shared_ptr<FclQuery> query_;
    std::shared_ptr<opx_ompl::CheckCounts> counts_;
};

// Uniform samples from an RNG seeded with `seed`.
class SeededSampler : public ompl::base::RealVectorStateSampler {
public:
    SeededSampler(const ompl::base::StateSpace *space, uint32_t seed) : ompl::base::RealVectorStateSampler(space) {
        rng_.setLocalSeed(seed);
    }
};

}  // namespace plan_bench
