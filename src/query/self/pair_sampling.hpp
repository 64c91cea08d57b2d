// Disabling the link pairs that never collide, as MoveIt's setup assistant
// does for an SRDF: the robot is posed at many random configurations
// (every moving joint uniform within its limits) and each enabled pair is
// tested at each; a pair that never touches is disabled, and, when asked,
// so is a pair that touches at every one (links meeting at their joint) or
// at the current poses (the default configuration).  Sampling can miss a
// rare configuration: more samples, fewer misses.
#pragma once

#include "robot/joint_tree.hpp"
#include "robot/linkset.hpp"

#include <cstdint>

namespace octoprox {

struct PairSamplingSettings {
    uint32_t samples = 10000;
    uint64_t seed = 1;
    bool also_always = false;  // also disable the pairs touching in every sample
    bool also_now = false;     // also disable the pairs touching at the current poses
};

struct PairSamplingOutcome {
    uint32_t now = 0;     // pairs disabled because they touch at the current poses
    uint32_t never = 0;   // pairs disabled because they never touched
    uint32_t always = 0;  // pairs disabled because they always touched
};

// Changes only `links`' pairs (its poses stay: the samples pose a copy).
// `joints` is the set's joint tree (links it does not move keep their pose).
PairSamplingOutcome disable_never_colliding_pairs(LinkSet &links, const JointTree &joints,
                                                  const PairSamplingSettings &settings);

}  // namespace octoprox
