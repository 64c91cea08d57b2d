// OctoProx as OMPL's collision checker: a state validity checker and a
// motion validator over one robot (an OctoProx link set made from URDF,
// with its SRDF's disabled pairs), an occupancy map and world objects.
//
// A planning state holds some of the robot's joints (the planning group);
// the others keep the positions of `CheckScene::joint_positions`.  A state
// is valid when no enabled link touches an obstacle cell or an enabled
// world object and, with self_collision, no enabled pair of links touches
// (opx_query_check_configurations, one row).  A motion is valid when every
// configuration on its straight joint-space line, at most `resolution`
// apart in every joint, is (opx_query_check_motion: the ends first, then
// ever finer midpoints, stopping at the first collision); with `certified`,
// when no configuration anywhere on the line collides
// (OPX_MOTION_CERTIFIED: no obstacle is missed between samples).
//
// Both classes are safe to call from several planner threads: each keeps
// one opx_query (an engine with its scratch memory) behind a mutex, so
// threads wait for each other; a parallel planner gets more from one
// checker per thread.  Nothing here changes the map, the world or the
// link set, so the caller may update the map between plans (not during).
#pragma once

#include <octoprox/octoprox.h>

#include <ompl/base/MotionValidator.h>
#include <ompl/base/StateValidityChecker.h>

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace opx_ompl {

// What states are checked against.  The pointers are not owned and must
// outlive the checkers.
struct CheckScene {
    const opx_octree *map = nullptr;      // may be NULL when world is set
    const opx_world *world = nullptr;     // NULL: the map alone
    const opx_linkset *robot = nullptr;   // its enabled links and pairs
    opx_pose base_pose = OPX_POSE_IDENTITY;  // the root link in the map frame
    // Every joint in model order (opx_linkset_get_joint_positions); the
    // planned ones are overwritten by each state.
    std::vector<double> joint_positions;
    // planned_joints[d]: the model index of the joint of state dimension d.
    std::vector<uint32_t> planned_joints;
    bool self_collision = true;
    // The largest joint step between two configurations a motion checks
    // (radians or metres).
    double resolution = 0.01;
    // Motions checked whole (OPX_MOTION_CERTIFIED) instead of sampled at
    // `resolution`: slower, and no thin obstacle between samples is missed.
    bool certified = false;
    int32_t unknown_policy = OPX_UNKNOWN_FREE;  // OPX_UNKNOWN_OCCUPIED: unseen space blocks
};

// Configurations checked so far, by states and within motions.
struct CheckCounts {
    std::atomic<uint64_t> states{0};
    std::atomic<uint64_t> motion_configurations{0};
    std::atomic<uint64_t> motions{0};
    uint64_t total() const { return states + motion_configurations; }
};

// One opx_query with the scene's world set, and the row a state becomes.
class SceneQuery {
public:
    explicit SceneQuery(const CheckScene &scene);
    ~SceneQuery();
    SceneQuery(const SceneQuery &) = delete;
    SceneQuery &operator=(const SceneQuery &) = delete;

    // Whether the configuration of `state` is free (see above).
    bool valid(const ompl::base::State *state);
    // The minimum distance to the map, objects and (with self_collision)
    // the robot itself at `state`, metres (0 when touching).
    double clearance(const ompl::base::State *state);
    // Checks the motion a -> b; false when it collides, *out_fraction
    // then the fraction of it (0 to 1) of the first colliding
    // configuration, *out_steps its step count.
    bool motion(const ompl::base::State *a, const ompl::base::State *b, double *out_fraction,
                uint64_t *out_steps, uint64_t *out_checked);

private:
    void fill(const ompl::base::State *state, std::vector<double> &row) const;

    const CheckScene &scene_;
    opx_query *query_ = nullptr;
    std::vector<double> row_, row_b_;
};

class StateValidityChecker : public ompl::base::StateValidityChecker {
public:
    StateValidityChecker(const ompl::base::SpaceInformationPtr &si, const CheckScene &scene,
                         std::shared_ptr<CheckCounts> counts);
    bool isValid(const ompl::base::State *state) const override;
    double clearance(const ompl::base::State *state) const override;

private:
    mutable std::mutex mutex_;
    mutable SceneQuery query_;
    std::shared_ptr<CheckCounts> counts_;
};

class MotionValidator : public ompl::base::MotionValidator {
public:
    MotionValidator(const ompl::base::SpaceInformationPtr &si, const CheckScene &scene,
                    std::shared_ptr<CheckCounts> counts);
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2) const override;
    bool checkMotion(const ompl::base::State *s1, const ompl::base::State *s2,
                     std::pair<ompl::base::State *, double> &last_valid) const override;

private:
    mutable std::mutex mutex_;
    mutable SceneQuery query_;
    std::shared_ptr<CheckCounts> counts_;
};

}  // namespace opx_ompl
