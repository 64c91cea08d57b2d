// What the batch queries read and answer: joint vectors as the caller
// holds them, root poses, and the settings of a configuration check.
#pragma once

#include "query/collision_types.hpp"
#include "query/distance_types.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace octoprox {

// `count` rows of `joint_count` doubles, `stride` bytes apart (never 0:
// the shims resolve a packed stride), in model order, or holding the
// active joints alone (`active`: their model indices, joint_count of them).
// Rows are copied out, so the caller's array needs no alignment.
struct JointRows {
    const unsigned char *bytes = nullptr;
    size_t count = 0, joint_count = 0, stride = 0;
    const std::vector<uint32_t> *active = nullptr;  // nullptr: rows in model order
    size_t active_model_count = 0;                   // with `active`: the model's joint count

    // The values read() gives: the model's joint count.
    size_t model_count() const { return active != nullptr ? active_model_count : joint_count; }

    // Row `row` as the caller holds it: joint_count values.
    void read_values(size_t row, double *out) const {
        std::memcpy(out, bytes + row * stride, joint_count * sizeof(double));
    }

    // Row `row` in model order: model_count() values, those of the
    // joints a row of active joints leaves out 0 (FK reads none of them).
    void read(size_t row, double *out) const {
        if (active == nullptr) return read_values(row, out);
        std::fill(out, out + active_model_count, 0.0);
        const unsigned char *values = bytes + row * stride;
        for (size_t i = 0; i < joint_count; ++i)
            std::memcpy(&out[(*active)[i]], values + i * sizeof(double), sizeof(double));
    }
};

class SensorOctree;
class World;

// What a batch checks the robot against: the octree, the world's enabled
// objects, or both (never neither).
struct Obstacles {
    const SensorOctree *tree = nullptr;
    const World *world = nullptr;
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
