// The brute-force self-collision oracle: every pair of shapes of two
// checked links (both enabled, the pair enabled) measured by the exact
// piece distances of oracle_pieces (a mesh triangle by triangle; a cylinder
// between an inscribed and a circumscribed prism, refined until the answer
// is decided).  Nothing is culled but by exact lower bounds (the gap of
// bounds), so every answer is the true one or honestly bracketed.
#pragma once

#include "oracle_pieces.hpp"
#include "oracle_robot.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace oracle {

// Which pairs of links are checked (the oracle's own copy of the rule).
class PairMask {
public:
    explicit PairMask(size_t links) : links_(links), enabled_(links * links, true) {}
    bool enabled(uint32_t a, uint32_t b) const { return enabled_[a * links_ + b]; }
    void set(uint32_t a, uint32_t b, bool on) { enabled_[a * links_ + b] = enabled_[b * links_ + a] = on; }
    size_t links() const { return links_; }

private:
    size_t links_;
    std::vector<bool> enabled_;
};

// The padded distance of two shapes lies in [low, high] (equal unless a
// cylinder is involved).
struct Bracket {
    double low = 0.0, high = 0.0;
};

// The padded distance of two placed shapes: exact between polytopes; with
// a cylinder, FCL's two solvers when they agree, else inscribed and
// circumscribed prisms.  Pieces `bound` or more apart are not measured: a
// result at or above `bound` only says "not nearer".
Bracket shape_pair_bracket(const PlacedShape &a, const PlacedShape &b,
                           double bound = std::numeric_limits<double>::infinity());

// A pair of shapes of two checked links (link_a < link_b).
struct ShapePairVerdict {
    const PlacedShape *a = nullptr, *b = nullptr;
    Verdict verdict = Verdict::kClear;
};

// The touch rule: padded distance <= 1e-9; within 1e-10 of it (1e-6 with
// a cylinder) a pair is ambiguous and not compared.
std::vector<ShapePairVerdict> self_verdicts(const std::vector<PlacedShape> &placed, const PairMask &pairs);

// The minimum padded distance over the checked pairs.
struct SelfMinimum {
    bool found = false;         // some checked pair (within the cutoff)
    Bracket distance{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    bool curved = false;        // a cylinder pair could be the nearest
};
SelfMinimum self_minimum(const std::vector<PlacedShape> &placed, const PairMask &pairs, double cutoff);

// The distance from p to the shape's core (0 inside a solid core; a mesh:
// its nearest triangle).
double point_core_distance(const Vec3 &p, const PlacedShape &shape);

}  // namespace oracle
