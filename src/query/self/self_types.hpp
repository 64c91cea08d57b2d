// Settings and answers of self-collision queries: a link set against
// itself, over the pairs of links it enables (LinkSet::pairs()).
#pragma once

#include "geometry/pose.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace octoprox {

struct SelfCollisionSettings {
    // 0: yes/no only; 1: stop at the first contact and keep it; N: up to N
    // contacts (one per touching pair of shapes), as CollisionSettings.
    uint32_t max_contacts = 1;
    bool penetration = false;  // depth, normal and point per contact
};

// Two shapes of two links that touch (link_a < link_b).
struct SelfContact {
    uint32_t link_a = 0, shape_a = 0, link_b = 0, shape_b = 0;
    int32_t attached_a = -1, attached_b = -1;  // the shapes' attached objects (PlacedShape::attached)
    double depth = 0.0;             // with penetration: paddings included, >= 0
    Vec3 normal = Vec3::Zero();     // moving link a by -depth * normal separates the pair
    Vec3 position = Vec3::Zero();   // midway between the two deepest points, map frame
};

struct SelfCollisionOutcome {
    bool collided = false;
    bool truncated = false;         // a contact beyond max_contacts (> 0) was left out
    uint64_t link_pairs = 0;        // enabled pairs whose link boxes overlap
    uint64_t narrow_tests = 0;      // exact piece-pair tests
};

struct SelfDistanceSettings {
    double cutoff = std::numeric_limits<double>::infinity();  // farther: "at least cutoff"
    bool signed_distance = false;   // overlap: minus the deepest penetration
    // Per link (null: every pair): pairs of two bodies whose links are
    // both unflagged are skipped (a motion that moves neither leaves their
    // distance as it is).
    const std::vector<uint8_t> *moving_links = nullptr;
};

// The nearest pair of shapes of two links (link_a < link_b).
struct SelfDistanceOutcome {
    bool found = false;             // an enabled pair within the cutoff
    double distance = std::numeric_limits<double>::infinity();
    Vec3 on_a = Vec3::Zero(), on_b = Vec3::Zero();  // witnesses on the padded shapes, map frame
    uint32_t link_a = 0, shape_a = 0, link_b = 0, shape_b = 0;
    int32_t attached_a = -1, attached_b = -1;
    uint64_t link_pairs = 0;        // enabled pairs measured beyond their boxes
    uint64_t narrow_tests = 0;
};

}  // namespace octoprox
