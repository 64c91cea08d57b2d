// Certified joint-space motions (OPX_MOTION_CERTIFIED): conservative
// advancement on exact distances.  At parameter s the robot is posed and
// each link's distance d to the obstacles measured (self-collision: the
// least distance of the enabled pairs); no link can reach an obstacle
// before it has moved d, and it moves at most rate(link) per unit of s
// (sweep_bounds.hpp), so the motion is free up to the least
// s + d / rate, where the check measures again.  Distances are searched
// only as far as each link moves in the next stretch of the motion (the
// cutoff stands in for a distance beyond it), a stretch that doubles
// while the steps take all of it.  Near a
// contact the steps shrink; once shorter than the tolerance, the
// configuration a tolerance ahead is tested, and a contact there ends the
// check with the first contact bracketed.  docs/geometry.md has the
// soundness argument.
#pragma once

#include "query/batch/batch_worker.hpp"
#include "query/motion/sweep_bounds.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

// Metres: a configuration this close to an obstacle counts as a contact
// (OPX_MOTION_CONTACT_DISTANCE), so a motion that grazes one ends.
constexpr double kCertifiedContact = 1e-8;

// Advancement steps a motion may take: beyond, the check gives up
// (OPX_ERROR_UNSUPPORTED) rather than run on for minutes.
constexpr uint64_t kMaxCertifiedSteps = 1000000;

struct CertifiedAnswer {
    double fraction = -1.0;  // the reported contact's parameter; -1: free
    uint64_t steps = 0;      // advancement steps
    uint64_t measured = 0;   // configurations measured

    bool collided() const { return fraction >= 0.0; }
};

struct CertifiedSettings {
    DistanceSettings distance;  // the obstacles as the collision settings say them
    bool self_collision = false;
    double tolerance = 1e-3;    // the bracket of the first contact, a fraction of the motion
};

// What a certified check reuses motion after motion.
struct CertifiedScratch {
    std::vector<double> sample, positions_start, positions_goal;
    std::vector<double> link_cutoffs;  // per link: how far it can still travel
    std::vector<uint8_t> moving_links; // per link: FK moves it along the motion
    SweepBounds bounds;
};

// The motion from `start` to `goal` (model order, joint_count() values of
// the worker's robot), the root at `base`.  The worker is prepared
// (BatchWorkers::prepare) with the world to check, if any.
CertifiedAnswer check_certified(BatchWorker &worker, CertifiedScratch &scratch, const SensorOctree *tree,
                                const JointTree &joints, const double *start, const double *goal, const Pose &base,
                                const CertifiedSettings &settings);

}  // namespace octoprox
