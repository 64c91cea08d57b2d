#include "octoprox_ompl.hpp"

#include <ompl/base/SpaceInformation.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace opx_ompl {
namespace {

void require(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

}  // namespace

SceneQuery::SceneQuery(const CheckScene &scene)
    : scene_(scene), row_(scene.joint_positions), row_b_(scene.joint_positions) {
    require(opx_query_create(nullptr, &query_), "opx_query_create");
    if (scene.world != nullptr) require(opx_query_set_world(query_, scene.world), "opx_query_set_world");
}

SceneQuery::~SceneQuery() { opx_query_destroy(query_); }

// The planning space is a RealVectorStateSpace, one dimension a planned joint.
void SceneQuery::fill(const ompl::base::State *state, std::vector<double> &row) const {
    const auto *values = state->as<ompl::base::RealVectorStateSpace::StateType>()->values;
    for (size_t d = 0; d < scene_.planned_joints.size(); ++d) row[scene_.planned_joints[d]] = values[d];
}

bool SceneQuery::valid(const ompl::base::State *state) {
    fill(state, row_);
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.self_collision = scene_.self_collision ? 1 : 0;
    request.unknown_policy = scene_.unknown_policy;
    request.joint_order = OPX_JOINTS_MODEL;
    uint8_t collided = 1;
    require(opx_query_check_configurations(query_, scene_.map, scene_.robot, row_.data(), 1, row_.size(), 0,
                                           &scene_.base_pose, 1, 0, &request, &collided, nullptr, 1),
            "opx_query_check_configurations");
    return collided == 0;
}

double SceneQuery::clearance(const ompl::base::State *state) {
    fill(state, row_);
    opx_batch_request request = OPX_BATCH_REQUEST_INIT;
    request.self_collision = scene_.self_collision ? 1 : 0;
    request.unknown_policy = scene_.unknown_policy;
    request.joint_order = OPX_JOINTS_MODEL;
    request.compute_distance = 1;
    uint8_t collided = 1;
    double distance = 0.0;
    require(opx_query_check_configurations(query_, scene_.map, scene_.robot, row_.data(), 1, row_.size(), 0,
                                           &scene_.base_pose, 1, 0, &request, &collided, &distance, 1),
            "opx_query_check_configurations");
    return distance;
}

bool SceneQuery::motion(const ompl::base::State *a, const ompl::base::State *b, double *out_fraction,
                        uint64_t *out_steps, uint64_t *out_checked) {
    fill(a, row_);
    fill(b, row_b_);
    opx_motion_request request = OPX_MOTION_REQUEST_INIT;
    request.resolution = scene_.resolution;
    if (scene_.certified) request.check = OPX_MOTION_CERTIFIED;
    request.self_collision = scene_.self_collision ? 1 : 0;
    request.unknown_policy = scene_.unknown_policy;
    request.joint_order = OPX_JOINTS_MODEL;
    opx_motion_result result = OPX_MOTION_RESULT_INIT;
    require(opx_query_check_motion(query_, scene_.map, scene_.robot, row_.data(), row_b_.data(), row_.size(),
                                   &scene_.base_pose, &request, &result),
            "opx_query_check_motion");
    *out_fraction = result.first_collision_fraction;
    *out_steps = result.steps;
    *out_checked = result.configurations_checked;
    return result.collided == 0;
}

StateValidityChecker::StateValidityChecker(const ompl::base::SpaceInformationPtr &si, const CheckScene &scene,
                                           std::shared_ptr<CheckCounts> counts)
    : ompl::base::StateValidityChecker(si), query_(scene), counts_(std::move(counts)) {
    specs_.clearanceComputationType = ompl::base::StateValidityCheckerSpecs::EXACT;
}

bool StateValidityChecker::isValid(const ompl::base::State *state) const {
    // Bounds first, as OMPL's own checkers leave them to the caller.
    if (!si_->satisfiesBounds(state)) return false;
    const std::lock_guard<std::mutex> lock(mutex_);
    ++counts_->states;
    return query_.valid(state);
}

double StateValidityChecker::clearance(const ompl::base::State *state) const {
    const std::lock_guard<std::mutex> lock(mutex_);
    ++counts_->states;
    return query_.clearance(state);
}

MotionValidator::MotionValidator(const ompl::base::SpaceInformationPtr &si, const CheckScene &scene,
                                 std::shared_ptr<CheckCounts> counts)
    : ompl::base::MotionValidator(si), query_(scene), counts_(std::move(counts)) {}

bool MotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const {
    std::pair<ompl::base::State *, double> unused(nullptr, 0.0);
    return checkMotion(s1, s2, unused);
}

// OMPL wants the last valid configuration before the first collision: the
// step before it on the motion's grid.
bool MotionValidator::checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                                  std::pair<ompl::base::State *, double> &last_valid) const {
    if (!si_->satisfiesBounds(s2)) {
        ++invalid_;
        return false;
    }
    double fraction = -1.0;
    uint64_t steps = 1, checked = 0;
    bool free = false;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        free = query_.motion(s1, s2, &fraction, &steps, &checked);
    }
    ++counts_->motions;
    counts_->motion_configurations += checked;
    if (free) {
        ++valid_;
        return true;
    }
    ++invalid_;
    last_valid.second = std::max(0.0, fraction - 1.0 / static_cast<double>(std::max<uint64_t>(steps, 1)));
    if (last_valid.first != nullptr)
        si_->getStateSpace()->interpolate(s1, s2, last_valid.second, last_valid.first);
    return false;
}

}  // namespace opx_ompl
