#include "query/batch/motion_check.hpp"

#include "base/error.hpp"
#include "query/batch/batch_split.hpp"

#include <cmath>

namespace octoprox {
namespace {

// Sample i of a motion of `steps` steps into scratch.sample.
const double *sample_at(MotionScratch &scratch, const double *start, const double *goal, uint64_t i, uint64_t steps) {
    if (i == steps) return goal;
    const double t = double(i) / double(steps);
    for (size_t j = 0; j < scratch.sample.size(); ++j) scratch.sample[j] = start[j] + t * (goal[j] - start[j]);
    return scratch.sample.data();
}

uint64_t largest_power_of_two_at_most(uint64_t n) {
    uint64_t p = 1;
    while (p <= n / 2) p *= 2;
    return p;
}

// Finds the first sample for which collides(i) holds, coarse to fine (see
// the header), checking no sample beyond the first collision found so far.
template <class Collides>
MotionAnswer first_colliding_sample(uint64_t steps, Collides &&collides) {
    MotionAnswer answer;
    answer.steps = steps;
    auto probe = [&](uint64_t i) {
        ++answer.samples_checked;
        if (collides(i)) answer.first_sample = static_cast<int64_t>(i);
    };
    auto beyond_first = [&](uint64_t i) { return answer.first_sample >= 0 && i >= uint64_t(answer.first_sample); };
    probe(0);
    if (!beyond_first(steps)) probe(steps);
    for (uint64_t s = largest_power_of_two_at_most(steps); s >= 1; s /= 2) {
        for (uint64_t i = s; i < steps && !beyond_first(i); i += 2 * s) probe(i);
    }
    return answer;
}

// The path query checked the map alone: the samples before its first
// collision are checked against themselves, in order.
void first_self_collision(BatchWorker &worker, MotionScratch &scratch, const double *start, const double *goal,
                          const Pose &base, MotionAnswer &answer) {
    const uint64_t end = answer.first_sample >= 0 ? uint64_t(answer.first_sample) : answer.steps + 1;
    SelfCollisionSettings yes_no;
    yes_no.max_contacts = 0;
    for (uint64_t i = 0; i < end; ++i) {
        const LinkSet &posed = worker.robot().pose(sample_at(scratch, start, goal, i, answer.steps), base);
        if (worker.context().self_collide(posed, yes_no).collided) {
            answer.first_sample = static_cast<int64_t>(i);
            return;
        }
    }
}

}  // namespace

double motion_steps(const PosedRobot &robot, MotionScratch &scratch, const double *start, const double *goal,
                    double resolution, double &largest) {
    robot.positions(start, scratch.positions_start);
    robot.positions(goal, scratch.positions_goal);
    largest = 0.0;
    for (size_t j = 0; j < scratch.positions_start.size(); ++j)
        largest = std::max(largest, std::fabs(scratch.positions_goal[j] - scratch.positions_start[j]));
    return std::max(1.0, std::ceil(largest / resolution));
}

void require_motion_steps(double steps, double largest, double resolution, const char *argument) {
    if (!(steps <= kMaxMotionSteps))
        throw_invalid(format("%s moves a joint by %g, %g steps at resolution %g; at most %g steps are checked",
                             argument, largest, steps, resolution, kMaxMotionSteps));
}

MotionAnswer check_motion(BatchWorker &worker, MotionScratch &scratch, const SensorOctree *tree,
                          const double *start, const double *goal, uint64_t steps, const Pose &base,
                          const MotionSettings &settings) {
    scratch.sample.resize(worker.robot().joint_count());
    return first_colliding_sample(steps, [&](uint64_t i) {
        return worker.collides_at(tree, sample_at(scratch, start, goal, i, steps), base, settings.collision,
                                  settings.self_collision);
    });
}

MotionAnswer check_motion_with_cost(BatchWorker &worker, QueryContext &context, const SensorOctree &tree,
                                    const LinkSet &links, const double *start, const double *goal, uint64_t steps,
                                    const Pose &base, const MotionSettings &settings) {
    MotionScratch scratch;
    scratch.sample.resize(worker.robot().joint_count());
    const size_t link_count = links.link_count();
    const double held = (double(steps) + 1.0) * double(link_count);
    if (held > kMaxCostPoses)
        throw_invalid(format("request.compute_cost keeps every sample's link poses: %llu samples of %zu links "
                             "are %.3g poses, more than %.3g; raise request.resolution or check the motion "
                             "without cost",
                             static_cast<unsigned long long>(steps + 1), link_count, held, kMaxCostPoses));
    std::vector<Pose> poses;
    poses.reserve((steps + 1) * link_count);
    for (uint64_t i = 0; i <= steps; ++i) {
        worker.robot().pose(sample_at(scratch, start, goal, i, steps), base);
        const std::vector<Pose> &sample_poses = worker.robot().link_poses();
        poses.insert(poses.end(), sample_poses.begin(), sample_poses.end());
    }
    PathSettings path;
    path.collision = settings.collision;
    MotionAnswer answer;
    answer.steps = steps;
    answer.samples_checked = steps + 1;
    answer.path = context.path(&tree, links, poses, steps + 1, path);
    answer.first_sample = answer.path.first_collision;
    if (settings.self_collision) first_self_collision(worker, scratch, start, goal, base, answer);
    return answer;
}

void check_motions(BatchWorkers &workers, const Obstacles &obstacles, const LinkSet &links, const JointTree &joints,
                   const JointRows &starts, const JointRows &goals, const BasePoses &bases,
                   const MotionSettings &settings, uint8_t *out_collided, double *out_fractions) {
    const size_t count = starts.count;
    const size_t tasks = task_count(settings.threads, count);
    workers.prepare(tasks, links, joints, obstacles.world);
    std::vector<uint64_t> steps(count);
    if (!settings.certified) {
        MotionScratch scratch;
        scratch.start.resize(starts.model_count()), scratch.goal.resize(goals.model_count());
        for (size_t m = 0; m < count; ++m) {
            starts.read(m, scratch.start.data()), goals.read(m, scratch.goal.data());
            double largest = 0.0;
            const double needed = motion_steps(workers[0].robot(), scratch, scratch.start.data(),
                                               scratch.goal.data(), settings.resolution, largest);
            if (!(needed <= kMaxMotionSteps))
                require_motion_steps(needed, largest, settings.resolution, format("motion %zu", m).c_str());
            steps[m] = static_cast<uint64_t>(needed);
        }
    }
    std::vector<MotionScratch> scratches(tasks);
    split_items(tasks, count, [&](size_t task, size_t begin, size_t end) {
        MotionScratch &scratch = scratches[task];
        scratch.start.resize(starts.model_count()), scratch.goal.resize(goals.model_count());
        for (size_t m = begin; m < end; ++m) {
            starts.read(m, scratch.start.data()), goals.read(m, scratch.goal.data());
            const MotionAnswer answer =
                settings.certified
                    ? MotionAnswer::of(check_certified(workers[task], scratch.certified, obstacles.tree, joints,
                                                       scratch.start.data(), scratch.goal.data(), bases.at(m),
                                                       settings.certified_settings))
                    : check_motion(workers[task], scratch, obstacles.tree, scratch.start.data(),
                                   scratch.goal.data(), steps[m], bases.at(m), settings);
            out_collided[m] = answer.collided() ? 1 : 0;
            if (out_fractions != nullptr) out_fractions[m] = answer.fraction();
        }
    });
}

}  // namespace octoprox
