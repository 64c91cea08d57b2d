// The certified motion rows of opx-bench-batch: the same motions checked
// by OPX_MOTION_CERTIFIED and sampled at 1/32 and 1/16 rad (VAMP's and
// pRRTC's step counts per unit of joint motion, here the largest joint
// step), each through one opx_query_check_motions call, the rounds
// interleaved; and how many motions each sampled check calls free while
// the certified one finds a collision.
#pragma once

#include <cstddef>
#include <vector>

#include "pipelines.hpp"

namespace batch_bench {

struct CertifiedTiming {
    double certified_us = 0.0, sampled_us = 0.0;   // per motion, median round; sampled at 1/32
    double certified_measured = 0.0;               // configurations measured per motion
    double sampled_checked = 0.0;                  // configurations checked per motion, at 1/32
    size_t motions = 0, certified_collided = 0, sampled_collided = 0;
    size_t missed_32 = 0, missed_16 = 0;           // sampled free, certified collides
    size_t unsound = 0;                            // sampled collides, certified free: must be 0
};

// The first `count` motions of the set (motion_goals).
CertifiedTiming time_certified_motions(const Workload &work, const std::vector<double> &goals, size_t count,
                                       uint32_t threads);

}  // namespace batch_bench
