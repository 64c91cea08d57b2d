// Settings and outputs of collision queries, shared by the engines.
#pragma once

#include "geometry/aabb.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

struct CollisionSettings {
    float threshold_log_odds = 0.0f;  // obstacle when a cell's log-odds >= this
    bool unknown_occupied = false;
    uint32_t max_contacts = 1;        // 0: yes/no only
    // Cost of uncertain and unknown space (paper IV.C).
    bool cost = false;
    float free_log_odds = 0.0f;       // uncertain when free <= log-odds < threshold
    double unknown_probability = 0.5;
    uint32_t max_cost_boxes = 16;     // the costliest kept
    bool penetration = false;         // depth, normal and point per contact
    bool point_extents = false;       // obstacle leaves are their point extents (octree_cell.hpp)
    Aabb region;                      // where unknown space counts
};

struct Contact {
    uint32_t link = 0, shape = 0;
    int32_t attached = -1;            // the shape's attached object (PlacedShape::attached)
    int cell_class = 0;
    double center[3] = {0, 0, 0};
    double size = 0.0;
    double probability = 0.0;
    double depth = 0.0;               // with settings.penetration
    double normal[3] = {0, 0, 0};
    double position[3] = {0, 0, 0};
};

struct CollisionOutcome {
    bool collided = false;
    bool truncated = false;
    uint64_t narrow_tests = 0;
};

}  // namespace octoprox
