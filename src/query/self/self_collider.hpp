// Self-collision of one link set at its current poses: every pair of two
// links that the set enables (LinkSet::pairs(): all but the SRDF's and the
// caller's disabled pairs) whose padded shapes touch, and the attached
// objects by their own rules (BodyPairs: not their link, not their touch
// links).  The body boxes (link_boxes.hpp) give the candidate pairs, the shape boxes the shape
// pairs within them, the exact tests (narrowphase/shape_pair.hpp) the
// answer.  One collider per thread: it keeps its scratch between calls,
// and reads the link set only, so a batch may call it on its own posed
// copies of a set.
#pragma once

#include "query/self/link_boxes.hpp"
#include "query/self/self_types.hpp"

#include <vector>

namespace octoprox {

class SelfCollider {
public:
    // Yes or no, stopping at the first touching pair (the batch's check).
    bool collides(const LinkSet &links);

    // Clears and fills `contacts` (one per touching pair of shapes, up to
    // settings.max_contacts).
    SelfCollisionOutcome collide(const LinkSet &links, const SelfCollisionSettings &settings,
                                 std::vector<SelfContact> &contacts);

    // The nearest pair of shapes over the enabled link pairs.
    SelfDistanceOutcome distance(const LinkSet &links, const SelfDistanceSettings &settings);

    // The pairs `filter` enables whose links touch, each once, into `out`
    // (pair sampling: which pairs ever or always collide).
    void touching_pairs(const LinkSet &links, const LinkPairs &filter, std::vector<LinkPair> &out);

private:
    // Calls visit(shape_a, shape_b) for the shape pairs of `pair` whose
    // boxes overlap, until it returns true; returns true then.
    template <class Visit>
    bool shape_pairs(const LinkSet &links, const LinkPair &pair, Visit &&visit) const;
    bool links_touch(const LinkSet &links, const LinkPair &pair, uint64_t &narrow_tests) const;
    void measure_pair(const LinkSet &links, const LinkPair &pair, SelfDistanceOutcome &best) const;
    void deepest_overlap(const LinkSet &links, SelfDistanceOutcome &best);

    LinkBoxes boxes_;
    std::vector<LinkBoxes::Candidate> candidates_;
    std::vector<SelfContact> overlap_scratch_;
};

}  // namespace octoprox
