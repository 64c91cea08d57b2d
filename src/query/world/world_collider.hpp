// A link set against the enabled objects of a World (world/world.hpp), at
// the set's current poses: each padded robot shape goes down the world's
// tree of object shapes by boxes, and the pairs whose boxes meet are
// decided by the exact shape-pair tests of self-collision
// (narrowphase/shape_pair.hpp).  The same code serves both engines: the
// query context composes its answer with the engine's octree answer.  One
// collider per context (it keeps its scratch between calls).
#pragma once

#include "robot/linkset.hpp"
#include "world/world.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace octoprox {

// A robot shape touching an object shape.
struct WorldContact {
    uint32_t link = 0, shape = 0;          // the robot's
    int32_t attached = -1;                 // the robot shape's attached object (PlacedShape::attached)
    uint32_t object = 0, object_shape = 0; // the world's
    double depth = 0.0;                    // with penetration: >= 0, the link's padding included
    Vec3 normal = Vec3::Zero();            // moving the link by -depth * normal separates the pair
    Vec3 position = Vec3::Zero();          // midway between the two deepest points, map frame
};

struct WorldCollisionSettings {
    // Contacts wanted in all (as CollisionSettings::max_contacts) and how
    // many the octree already holds: the world adds up to the difference.
    uint32_t max_contacts = 1;
    size_t kept_before = 0;
    bool penetration = false;
};

struct WorldCollisionOutcome {
    bool collided = false;
    bool truncated = false;   // a touching pair beyond max_contacts (> 0) was left out
    uint64_t narrow_tests = 0;
};

// The nearest pair of a robot shape and an object shape.
struct WorldDistance {
    bool found = false;  // a pair nearer than the bound
    double distance = std::numeric_limits<double>::infinity();
    Vec3 on_link = Vec3::Zero(), on_object = Vec3::Zero();  // witnesses, map frame
    uint32_t link = 0, shape = 0, object = 0, object_shape = 0;
    int32_t attached = -1;  // the robot shape's attached object
    uint64_t narrow_tests = 0;
};

class WorldCollider {
public:
    // Clears and fills `contacts` (one per touching pair of shapes).
    WorldCollisionOutcome collide(const World &world, const LinkSet &links, const WorldCollisionSettings &settings,
                                  std::vector<WorldContact> &contacts);

    // The nearest pair strictly nearer than `bound` (found = false: none).
    // Signed: a touching pair counts as minus its penetration depth.  With
    // per_link (one bound per link on entry, infinity for none), each
    // link's own minimum replaces its entry when nearer.
    WorldDistance distance(const World &world, const LinkSet &links, double bound, bool signed_distance,
                           std::vector<double> *per_link);

    // Yes or no, stopping at the first touching pair (paths, batches and
    // motions); allocates nothing once its scratch has grown.
    bool collides(const World &world, const LinkSet &links, uint64_t &narrow_tests);

private:
    // Calls visit(object shape) for each object shape whose box is within
    // the touch tolerance of `shape`'s, until it returns true.
    template <class Visit>
    bool overlapping(const WorldIndex &index, const PlacedShape &shape, Visit &&visit);
    // The shape's nearest object shape below best.distance, into best.
    void nearest(const WorldIndex &index, const PlacedShape &shape, bool signed_distance, WorldDistance &best);

    std::vector<int32_t> stack_;
    std::vector<WorldContact> no_contacts_;  // collides(): stays empty
};

}  // namespace octoprox
