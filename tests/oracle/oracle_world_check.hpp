// Queries with world objects (world.h, opx_query_set_world) checked
// against brute force.  The oracle sees the robot's links and the objects
// as one set of placed shapes (the objects after the links, object o as
// link robot_links + o, padding 0) and checks only the pairs of a link and
// an object (a PairMask), with the exact piece distances of oracle_self:
// every pair measured, nothing culled but by exact lower bounds.
//
//   objects only (tree NULL): collided, the contact set (equal to the
//     touching pairs up to ambiguous ones), max_contacts 0, 1 and a
//     truncated N; the distance, its pair and witnesses, per-link minima,
//     a cutoff, the signed distance;
//   beside an octree: the answer with both equals the union (collision)
//     and the minimum (distance, per link) of the two asked apart, and
//     the direct and amortized engines agree.
#pragma once

#include "oracle_self.hpp"

#include <octoprox/octoprox.h>

#include <cstdint>
#include <string>
#include <vector>

namespace oracle {

struct WorldCase {
    // The robot's enabled shapes (links 0 .. robot_links-1), then the
    // enabled objects' shapes (link robot_links + object index).
    const std::vector<PlacedShape> *placed = nullptr;
    const PairMask *pairs = nullptr;  // only (link, object) pairs enabled
    uint32_t robot_links = 0;
    std::string label;
};

// The mask of every (robot link, object) pair.
PairMask link_object_pairs(uint32_t robot_links, uint32_t objects);

class WorldChecker {
public:
    explicit WorldChecker(std::string test_name) : name_(std::move(test_name)) {}

    // `query` has the world set; the octree is not used.
    void check_objects(opx_query *query, const opx_linkset *links, const WorldCase &c);
    // `with_world[e]` has the world set, `plain[e]` not, per engine e
    // (direct, amortized).
    void check_with_map(opx_query *const with_world[2], opx_query *const plain[2], const opx_octree *tree,
                        const opx_linkset *links, const WorldCase &c);
    void fail(const std::string &message) { mismatch(message); }
    // Prints the summary line; returns the exit code (0, or 1 on mismatches).
    int finish(double seconds) const;

private:
    struct Answer {
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        std::vector<opx_contact> contacts;
    };
    Answer collide(opx_query *query, const opx_octree *tree, const opx_linkset *links, const WorldCase &c,
                   uint32_t max_contacts);
    void compare_contacts(const WorldCase &c, const std::vector<ShapePairVerdict> &oracle, const Answer &all);
    void check_limits(opx_query *query, const opx_linkset *links, const WorldCase &c, size_t touching);
    void check_distance(opx_query *query, const opx_linkset *links, const WorldCase &c, bool collided);
    void check_per_link(opx_query *query, const opx_linkset *links, const WorldCase &c);
    void check_witnesses(const WorldCase &c, const opx_distance_result &r);
    void check_union(opx_query *with_world, opx_query *plain, const opx_octree *tree, const opx_linkset *links,
                     const WorldCase &c, Answer &out);
    void check_minimum(opx_query *with_world, opx_query *plain, const opx_octree *tree, const opx_linkset *links,
                       const WorldCase &c, int32_t signed_distance, double &out);
    const PlacedShape *find(const WorldCase &c, uint32_t link, uint32_t shape) const;
    void mismatch(const std::string &message);

    std::string name_;
    uint64_t states_ = 0, collided_ = 0, touching_pairs_ = 0, ambiguous_pairs_ = 0, mismatches_ = 0;
    uint64_t distances_ = 0, curved_minima_ = 0, map_states_ = 0, map_object_nearest_ = 0;
};

}  // namespace oracle
