// What the batch queries read and answer: joint vectors as the caller
// holds them, root poses, and the settings of a configuration check.
#pragma once

#include "query/collision_types.hpp"
#include "query/distance_types.hpp"

#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace octoprox {

// `count` rows of `joint_count` doubles (model order), `stride` bytes
// apart (never 0: the shims resolve a packed stride).  Rows are copied
// out, so the caller's array needs no alignment.
struct JointRows {
    const unsigned char *bytes = nullptr;
    size_t count = 0, joint_count = 0, stride = 0;

    void read(size_t row, double *out) const {
        std::memcpy(out, bytes + row * stride, joint_count * sizeof(double));
    }
};

// The root link's pose (map frame): one for every row, or one per row.
struct BasePoses {
    std::vector<Pose> poses;  // never empty (the shims put the identity when none is given)

    const Pose &at(size_t row) const { return poses.size() == 1 ? poses[0] : poses[row]; }
};

struct ConfigurationSettings {
    CollisionSettings collision;   // max_contacts 0 and no cost: yes or no
    bool self_collision = false;   // also the link set's own enabled pairs
    bool distance = false;         // also the minimum distance
    DistanceSettings distance_settings;
    size_t threads = 1;
};

struct ConfigurationAnswer {
    bool collided = false;
    double distance = std::numeric_limits<double>::infinity();  // with settings.distance
};

// Where a batch writes its answers (the caller's arrays).
struct ConfigurationOutputs {
    uint8_t *collided = nullptr;   // 0 or 1 per row
    double *distances = nullptr;   // with settings.distance
};

}  // namespace octoprox
