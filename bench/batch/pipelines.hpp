// The timed pipelines of opx-bench-batch, each over one configuration set:
//   single calls      opx_linkset_set_joint_positions, then opx_query_collide
//                     (yes/no) and, without a contact, opx_query_self_collide,
//                     per configuration: the one-call way
//   batch N threads   one opx_query_check_configurations call
//   fcl               FclCheck: world, then self; FK (placing the objects) untimed
// and the motion batch (opx_query_check_motions).  The time of each is the
// median of its rounds (time_interleaved).
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "configurations.hpp"
#include "fcl_check.hpp"

namespace batch_bench {

struct Timing {
    double us_per_configuration = 0.0;  // the median round's
    double fastest_us = 0.0;            // the fastest round's
    std::vector<uint8_t> collided;      // per configuration
};

struct Workload {
    Robot &robot;
    const Scene &scene;
    const ConfigurationSet &set;
    bool self_collision = false;
    int rounds = 3;
};

// A pipeline answers configurations [begin, end) of the set into the same
// entries of `collided` and returns the milliseconds of its timed part.
using Pipeline = std::function<double(std::vector<uint8_t> &collided, size_t begin, size_t end)>;

Pipeline single_calls(const Workload &work);
Pipeline batch_call(const Workload &work, uint32_t threads);
Pipeline fcl_calls(const Workload &work, FclCheck &fcl);

// Each pipeline once untimed (its answers), then work.rounds rounds; in a
// round every pipeline answers the whole set (a batch pipeline in one
// call, as a planner's calls come one after another), the order rotating
// from round to round.
std::vector<Timing> time_interleaved(const Workload &work, const std::vector<Pipeline> &pipelines);

constexpr double kMotionResolution = 0.02;  // rad

struct MotionTiming {
    double motions_per_second = 0.0;
    double us_per_configuration = 0.0;       // per configuration checked
    double configurations_per_motion = 0.0;  // checked, coarse to fine
    size_t motions = 0, collided = 0;
};

// The first `count` motions of the set (motion_goals).
MotionTiming time_motions(const Workload &work, const std::vector<double> &goals, size_t count, uint32_t threads);

}  // namespace batch_bench
