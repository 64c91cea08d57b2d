#include "query/batch/certified_motion.hpp"

#include "base/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {
namespace {

// A measured distance d may exceed the true one by rounding (at most about
// 2e-7 d with a cylinder, docs/geometry.md) and a shape collides up to the
// 1e-9 m touch tolerance: the distance a link may travel and still be
// apart is at least d (1 - 1e-6) - 2e-9 m.
double travel_allowed(double distance) { return distance * (1.0 - 1e-6) - 2e-9; }

// How far distances are searched when the motion has `remaining` of its
// parameter left: a little beyond what a link can still travel (a link
// that far away is free for the rest), and never below a contact.
// The first search reaches what the links travel in this much of the motion.
constexpr double kFirstReach = 0.125;

double cutoff_for(double rate, double remaining) { return rate * remaining * (1.0 + 1e-5) + 2.0 * kCertifiedContact; }

struct Measure {
    bool contact = false;
    double step = std::numeric_limits<double>::infinity();  // free for this much more of the parameter
};

class Advancer {
public:
    Advancer(BatchWorker &worker, CertifiedScratch &scratch, const SensorOctree *tree, const double *start,
             const double *goal, const Pose &base, const CertifiedSettings &settings)
        : worker_(worker), scratch_(scratch), tree_(tree), start_(start), goal_(goal), base_(base),
          settings_(settings) {}

    // The configuration at `s`, measured as far as its links travel in
    // the `remaining` part of the motion (0: a contact test).
    Measure measure(double s, double remaining, CertifiedAnswer &answer) {
        const bool first = answer.measured++ == 0;
        const LinkSet &posed = worker_.robot().pose(sample_at(s), base_);
        Measure m;
        measure_obstacles(posed, remaining, first, m);
        if (settings_.self_collision && !m.contact) measure_self(posed, remaining, first, m);
        return m;
    }

private:
    const double *sample_at(double s) {
        if (s == 1.0) return goal_;
        for (size_t j = 0; j < scratch_.sample.size(); ++j) scratch_.sample[j] = start_[j] + s * (goal_[j] - start_[j]);
        return scratch_.sample.data();
    }

    void measure_obstacles(const LinkSet &posed, double remaining, bool first, Measure &m) {
        const SweepBounds &bounds = scratch_.bounds;
        DistanceSettings d = settings_.distance;
        d.cutoff = cutoff_for(bounds.largest_rate(), remaining);
        std::vector<double> &cutoffs = scratch_.link_cutoffs;
        cutoffs.resize(posed.link_count());
        // A link that does not move is apart for the whole motion once it
        // is apart at the start: it is searched there alone.
        for (uint32_t link = 0; link < cutoffs.size(); ++link)
            cutoffs[link] = bounds.rate(link) > 0.0 || first ? cutoff_for(bounds.rate(link), remaining) : -1.0;
        d.link_cutoffs = &cutoffs;
        QueryContext &context = worker_.context();
        context.distance(tree_, posed, d, true);
        const std::vector<double> &per_link = context.link_distances();
        for (uint32_t link = 0; link < per_link.size(); ++link) {
            if (cutoffs[link] < 0.0) continue;  // not searched
            const double distance = std::min(per_link[link], cutoffs[link]);
            if (distance <= kCertifiedContact) {
                m.contact = true;
                return;
            }
            const double rate = bounds.rate(link);
            if (rate > 0.0) m.step = std::min(m.step, travel_allowed(distance) / rate);
        }
    }

    // After the obstacles: the pairs need only be searched as far as they
    // can travel in the step the obstacles allow (self-distance is the
    // costly query for a robot of many meshes).
    // Pairs of links that do not move keep their distance: the start's
    // yes/no test settles them, and the distances skip them.
    void measure_self(const LinkSet &posed, double remaining, bool first, Measure &m) {
        const double rate = scratch_.bounds.self_rate();
        std::vector<uint8_t> &moving = scratch_.moving_links;
        if (first) {
            SelfCollisionSettings yes_no;
            yes_no.max_contacts = 0;
            if (worker_.context().self_collide(posed, yes_no).collided) {
                m.contact = true;
                return;
            }
            moving.resize(posed.link_count());
            for (uint32_t link = 0; link < moving.size(); ++link) moving[link] = scratch_.bounds.rate(link) > 0.0;
        }
        SelfDistanceSettings self;
        self.moving_links = &moving;
        self.cutoff = cutoff_for(rate, std::min(remaining, m.step));
        const SelfDistanceOutcome nearest = worker_.context().self_distance(posed, self);
        const double distance = nearest.found ? std::min(nearest.distance, self.cutoff) : self.cutoff;
        if (distance <= kCertifiedContact) m.contact = true;
        else if (rate > 0.0) m.step = std::min(m.step, travel_allowed(distance) / rate);
    }

    BatchWorker &worker_;
    CertifiedScratch &scratch_;
    const SensorOctree *tree_;
    const double *start_, *goal_;
    const Pose &base_;
    const CertifiedSettings &settings_;
};

}  // namespace

// Every step is free up to where it lands (the bounds above), so the first
// contact found at s has none before it; a contact found by the test a
// tolerance ahead of s has none before s, which is within the tolerance.
CertifiedAnswer check_certified(BatchWorker &worker, CertifiedScratch &scratch, const SensorOctree *tree,
                                const JointTree &joints, const double *start, const double *goal, const Pose &base,
                                const CertifiedSettings &settings) {
    PosedRobot &robot = worker.robot();
    scratch.sample.resize(robot.joint_count());
    robot.positions(start, scratch.positions_start);
    robot.positions(goal, scratch.positions_goal);
    scratch.bounds.compute(joints, robot.pose(start, base), scratch.positions_start, scratch.positions_goal,
                           settings.self_collision);
    Advancer advancer(worker, scratch, tree, start, goal, base, settings);
    CertifiedAnswer answer;
    // Distances are searched only as far as the links travel in `reach`
    // of the parameter: a far search of a mesh link costs much, and near
    // obstacles the step is short anyway.  It doubles after a step that
    // took all of it and follows the step otherwise.
    double s = 0.0, tested_until = 0.0, reach = kFirstReach;
    for (;;) {
        const double searched = std::min(1.0 - s, reach);
        const Measure here = advancer.measure(s, searched, answer);
        reach = here.step >= searched ? 2.0 * reach : std::max(2.0 * here.step, settings.tolerance);
        if (here.contact) {
            answer.fraction = s;
            return answer;
        }
        if (!(s + here.step < 1.0)) return answer;
        if (here.step < settings.tolerance && s >= tested_until) {
            tested_until = std::min(1.0, s + settings.tolerance);
            if (advancer.measure(tested_until, 0.0, answer).contact) {
                answer.fraction = tested_until;
                return answer;
            }
        }
        const double next = s + here.step;
        if (!(next > s) || answer.steps >= kMaxCertifiedSteps)
            throw ApiError(OPX_ERROR_UNSUPPORTED,
                           format("the certified check took %llu steps up to %.17g of the motion without settling: "
                                  "the motion passes very close to an obstacle for a long stretch; check shorter "
                                  "motions", static_cast<unsigned long long>(answer.steps), s));
        s = next;
        ++answer.steps;
    }
}

}  // namespace octoprox
