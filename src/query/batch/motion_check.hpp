// Joint-space motions (opx_query_check_motion, _check_motions): a straight
// line from a start to a goal joint vector, checked at samples close
// enough that no joint position moves more than the resolution between
// two of them.  Sample i of n steps is start + (i / n) (goal - start)
// (the goal itself for i = n); positions follow linearly, mimic joints
// included.  The answer is the first colliding sample, found coarse to
// fine: both ends, then the midpoints of ever finer halvings, skipping
// samples beyond the first collision found so far.  A colliding motion is
// thus found after few checks, and the first sample is still exact.
#pragma once

#include "query/batch/batch_worker.hpp"
#include "query/batch/certified_motion.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

struct MotionSettings {
    CollisionSettings collision;  // max_contacts 0; cost: the swept cost (check_motion_with_cost)
    double resolution = 0.01;     // largest joint step between samples, rad or m (> 0)
    bool self_collision = false;
    size_t threads = 1;           // batches of motions
    bool certified = false;       // OPX_MOTION_CERTIFIED: resolution unused (certified_motion.hpp)
    CertifiedSettings certified_settings;
};

struct MotionAnswer {
    int64_t first_sample = -1;  // -1: no sample collides
    uint64_t steps = 0;         // samples are steps + 1
    uint64_t samples_checked = 0;
    PathOutcome path;           // check_motion_with_cost only
    bool certified = false;     // a certified check: its answer below, steps its advancements
    double certified_fraction = -1.0;

    bool collided() const { return certified ? certified_fraction >= 0.0 : first_sample >= 0; }
    // The first colliding sample's place along the motion in [0, 1]; -1: none.
    double fraction() const {
        if (certified) return certified_fraction;
        return first_sample < 0 ? -1.0 : steps == 0 ? 0.0 : double(first_sample) / double(steps);
    }
    static MotionAnswer of(const CertifiedAnswer &a) {
        MotionAnswer answer;
        answer.certified = true;
        answer.certified_fraction = a.fraction;
        answer.steps = a.steps, answer.samples_checked = a.measured;
        return answer;
    }
};

// What one motion check needs besides its worker, reused motion after motion.
struct MotionScratch {
    std::vector<double> start, goal, sample, positions_start, positions_goal;
    CertifiedScratch certified;
};

// The steps a motion needs at `resolution`: at least 1, and beyond
// kMaxMotionSteps (up to +infinity) for a motion no caller would wait for,
// which the callers refuse.  `largest` gets the largest joint move.
constexpr double kMaxMotionSteps = 1e7;
double motion_steps(const PosedRobot &robot, MotionScratch &scratch, const double *start, const double *goal,
                    double resolution, double &largest);
// An invalid-argument error unless steps <= kMaxMotionSteps.
void require_motion_steps(double steps, double largest, double resolution, const char *argument);

// One motion, without cost; `steps` from motion_steps.  The worker is
// prepared (BatchWorkers::prepare) with the world to check, if any.
MotionAnswer check_motion(BatchWorker &worker, MotionScratch &scratch, const SensorOctree *tree,
                          const double *start, const double *goal, uint64_t steps, const Pose &base,
                          const MotionSettings &settings);

// The most link poses a motion with the swept cost holds (every sample's,
// for the path query's union of swept cells): 2^21, about 200 MB.
constexpr double kMaxCostPoses = double(uint64_t{1} << 21);

// One motion with the swept cost: every sample's poses (FK on the worker's
// robot) go through `context`'s path query (with the context's world), whose
// cost boxes it then holds.  An invalid-argument error naming compute_cost
// when (steps + 1) x links exceeds kMaxCostPoses.
MotionAnswer check_motion_with_cost(BatchWorker &worker, QueryContext &context, const SensorOctree &tree,
                                    const LinkSet &links, const double *start, const double *goal, uint64_t steps,
                                    const Pose &base, const MotionSettings &settings);

// Many motions: row m of `starts` to row m of `goals` (at bases.at(m)),
// split over settings.threads workers.  out_fractions may be null.
void check_motions(BatchWorkers &workers, const Obstacles &obstacles, const LinkSet &links, const JointTree &joints,
                   const JointRows &starts, const JointRows &goals, const BasePoses &bases,
                   const MotionSettings &settings, uint8_t *out_collided, double *out_fractions);

}  // namespace octoprox
