#include "plan_checkers.hpp"

#include "pr2_fcl.hpp"

#include <ompl/base/SpaceInformation.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>
#include <utility>

namespace plan_bench {
namespace {

void require(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

void fill(const opx_ompl::CheckScene &scene, const ompl::base::State *state, std::vector<double> &row) {
    const double *values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
    for (size_t d = 0; d < scene.planned_joints.size(); ++d) row[scene.planned_joints[d]] = values[d];
}

}  // namespace

FclQuery::FclQuery(batch_bench::Robot &robot, fcl::CollisionObjectd &octree, const opx_ompl::CheckScene &scene)
    : scene_(scene), check_(robot, octree), row_(scene.joint_positions), a_(row_), b_(row_) {
    require(opx_linkset_clone(scene.robot, &copy_), "opx_linkset_clone");
}

FclQuery::~FclQuery() { opx_linkset_destroy(copy_); }

bool FclQuery::free_at(const std::vector<double> &row) {
    require(opx_linkset_set_joint_positions(copy_, row.data(), row.size(), &scene_.base_pose),
            "opx_linkset_set_joint_positions");
    check_.place(paper_tables::link_poses(copy_));
    return !check_.world_collides() && !(scene_.self_collision && check_.self_collides());
}

bool FclQuery::valid(const ompl::base::State *state) {
    fill(scene_, state, row_);
    return free_at(row_);
}

// The grid of opx_query_check_motion: n steps, configuration i at i / n;
// the ends, then the midpoints of ever finer halves, first collision found
// ending the check.
bool FclQuery::motion(const ompl::base::State *a, const ompl::base::State *b, double *out_fraction,
                      uint64_t *out_steps, uint64_t *out_checked) {
    fill(scene_, a, a_);
    fill(scene_, b, b_);
    double longest = 0.0;
    for (uint32_t j : scene_.planned_joints) longest = std::max(longest, std::fabs(b_[j] - a_[j]));
    const uint64_t n = std::max<uint64_t>(1, static_cast<uint64_t>(std::ceil(longest / scene_.resolution)));
    *out_steps = n;
    *out_checked = 0;
    uint64_t first = n + 1;
    auto check = [&](uint64_t i) {
        const double t = static_cast<double>(i) / static_cast<double>(n);
        for (uint32_t j : scene_.planned_joints) row_[j] = i == n ? b_[j] : a_[j] + t * (b_[j] - a_[j]);
        ++*out_checked;
        if (!free_at(row_)) first = std::min(first, i);
    };
    check(0);
    if (first > n) check(n);
    std::deque<std::pair<uint64_t, uint64_t>> halves{{0, n}};
    while (!halves.empty()) {
        const auto [lo, hi] = halves.front();
        halves.pop_front();
        if (hi - lo < 2) continue;
        const uint64_t mid = lo + (hi - lo) / 2;
        if (mid >= first) continue;
        check(mid);
        halves.emplace_back(lo, mid);
        halves.emplace_back(mid, hi);
    }
    *out_fraction = first <= n ? static_cast<double>(first) / static_cast<double>(n) : -1.0;
    return first > n;
}

bool FclValidityChecker::isValid(const ompl::base::State *state) const {
    if (!si_->satisfiesBounds(state)) return false;
    ++counts_->states;
    return query_->valid(state);
}

bool FclMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const {
    std::pair<ompl::base::State *, double> unused(nullptr, 0.0);
    return checkMotion(s1, s2, unused);
}

bool FclMotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                                     std::pair<ompl::base::State *, double> &last_valid) const {
    if (!si_->satisfiesBounds(s2)) {
        ++invalid_;
        return false;
    }
    double fraction = -1.0;
    uint64_t steps = 1, checked = 0;
    const bool free = query_->motion(s1, s2, &fraction, &steps, &checked);
    ++counts_->motions;
    counts_->motion_configurations += checked;
    if (free) {
        ++valid_;
        return true;
    }
    ++invalid_;
    last_valid.second = std::max(0.0, fraction - 1.0 / static_cast<double>(steps));
    if (last_valid.first != nullptr) si_->getStateSpace()->interpolate(s1, s2, last_valid.second, last_valid.first);
    return false;
}

}  // namespace plan_bench
