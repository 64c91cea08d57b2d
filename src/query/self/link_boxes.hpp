// The broad phase of self-collision: one box per body (a link's own padded
// shapes, or an object attached to a link), swept along the axis where the
// bodies spread most (sort and sweep), giving the pairs of bodies whose
// boxes overlap; and, for distance, every pair with the distance of its
// boxes.  A link set of n bodies costs a sort of n boxes plus the
// overlapping pairs, not n^2 tests.
//
// Bodies are numbered links first (body l is link l), then attached
// objects (body link_count + i is attached object i).
#pragma once

#include "robot/linkset.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

// Two bodies, ordered by their links (a's link < b's link: the pairs
// checked never share a link).
struct LinkPair {
    uint32_t a = 0, b = 0;
};

// Which pairs of bodies self-collision checks: two links as `link_pairs`
// says; an attached object and a link unless the link is the object's own
// or one of its touch links (the link pairs do not apply: MoveIt's touch
// links); two attached objects unless they hang on the same link.
class BodyPairs {
public:
    BodyPairs(const LinkSet &links, const LinkPairs &link_pairs)
        : links_(links), pairs_(link_pairs), link_count_(static_cast<uint32_t>(links.link_count())) {}

    bool enabled(uint32_t a, uint32_t b) const {
        const uint32_t n = link_count_;
        if (a < n && b < n) return pairs_.enabled(a, b);
        if (a >= n && b >= n) return links_.attached(a - n).link != links_.attached(b - n).link;
        return a >= n ? links_.attached_meets_link(a - n, b) : links_.attached_meets_link(b - n, a);
    }

private:
    const LinkSet &links_;
    const LinkPairs &pairs_;
    uint32_t link_count_;
};

class LinkBoxes {
public:
    // The boxes of the bodies of enabled links that have shapes (attached
    // objects only `with_attached`), at the set's poses, grown by the touch
    // tolerance.
    void update(const LinkSet &links, bool with_attached = true);

    // Calls visit(pair) for each pair of bodies whose boxes overlap and
    // which `filter` enables, until visit returns true; returns true then.
    template <class Visit>
    bool overlapping(const BodyPairs &filter, Visit &&visit) const {
        const size_t n = sorted_.size();
        for (size_t i = 0; i < n; ++i) {
            const Entry &x = sorted_[i];
            for (size_t j = i + 1; j < n && sorted_[j].box.lo[axis_] <= x.box.hi[axis_]; ++j) {
                const Entry &y = sorted_[j];
                if (!x.box.overlaps(y.box) || !filter.enabled(x.body, y.body)) continue;
                if (visit(ordered(x, y))) return true;
            }
        }
        return false;
    }

    // Every pair `filter` enables whose boxes are nearer than `cutoff`,
    // with that distance (a lower bound of the bodies' distance), nearest
    // first, into `out`.
    struct Candidate {
        LinkPair pair;
        double lower = 0.0;
    };
    void nearer_than(const BodyPairs &filter, double cutoff, std::vector<Candidate> &out) const;

    // The body's placed shapes: placed()[first(body)] .. + count(body).
    uint32_t first(uint32_t body) const { return ranges_[body].first; }
    uint32_t count(uint32_t body) const { return ranges_[body].count; }

private:
    struct Entry {
        Aabb box;
        uint32_t body, link;  // link: the body's link (itself, or the link an object hangs on)
    };
    struct Range {
        uint32_t first = 0, count = 0;
    };
    static LinkPair ordered(const Entry &x, const Entry &y) {
        return x.link < y.link || (x.link == y.link && x.body < y.body) ? LinkPair{x.body, y.body}
                                                                        : LinkPair{y.body, x.body};
    }
    void choose_axis();

    std::vector<Entry> sorted_;   // by box.lo[axis_]
    std::vector<Range> ranges_;   // per body
    int axis_ = 0;
};

}  // namespace octoprox
