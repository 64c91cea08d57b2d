// One robot state checked against the self-collision oracle: the library's
// opx_query_self_collide (max_contacts 0, 1, a truncated N, all) and
// opx_query_self_distance (exact, with a cutoff, signed) through the C ABI,
// compared with oracle_self's brute-force answers.
#pragma once

#include "oracle_random.hpp"
#include "oracle_self.hpp"

#include <octoprox/octoprox.h>

#include <cstdint>
#include <string>
#include <vector>

namespace oracle {

// Pairs of `count` links enabled at random (each disabled with probability
// `disabled`), the same in the oracle's mask and in the library's link set.
PairMask random_pairs(Rng &rng, opx_linkset *links, size_t count, double disabled);

struct SelfCase {
    const std::vector<PlacedShape> *placed = nullptr;
    const PairMask *pairs = nullptr;
    std::string label;  // e.g. "arm 3 configuration 17 (seed 42)"
};

class SelfChecker {
public:
    explicit SelfChecker(std::string test_name) : name_(std::move(test_name)) {}

    // Returns false on a mismatch (the first few are printed in full).
    bool check(opx_query *query, const opx_linkset *links, const SelfCase &c);
    void fail(const std::string &message) { mismatch(message); }
    // Prints the summary line; returns the exit code (0, or 1 on mismatches).
    int finish(double seconds) const;

private:
    struct Answer;
    Answer collide(opx_query *query, const opx_linkset *links, const SelfCase &c, uint32_t max_contacts);
    void compare_contacts(const SelfCase &c, const std::vector<ShapePairVerdict> &oracle, const Answer &all);
    void check_limits(opx_query *query, const opx_linkset *links, const SelfCase &c, size_t touching);
    void check_distance(opx_query *query, const opx_linkset *links, const SelfCase &c, bool collided);
    void check_witnesses(const SelfCase &c, const opx_self_distance_result &r);
    const PlacedShape *find(const SelfCase &c, uint32_t link, uint32_t shape) const;
    void mismatch(const std::string &message);

    std::string name_;
    uint64_t states_ = 0, collided_ = 0, touching_pairs_ = 0, ambiguous_pairs_ = 0, mismatches_ = 0;
    uint64_t distances_ = 0, curved_minima_ = 0, undecided_ = 0;
};

}  // namespace oracle
