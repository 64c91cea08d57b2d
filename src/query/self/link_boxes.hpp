// The broad phase of self-collision: one box per link (the union of its
// padded shapes' boxes), swept along the axis where the links spread most
// (sort and sweep), giving the pairs of links whose boxes overlap; and, for
// distance, every pair with the distance of its boxes.  A link set of n
// links costs a sort of n boxes plus the overlapping pairs, not n^2 tests.
#pragma once

#include "robot/linkset.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

struct LinkPair {
    uint32_t a = 0, b = 0;  // a < b
};

class LinkBoxes {
public:
    // The boxes of the enabled links that have shapes, at the set's poses,
    // grown by the touch tolerance.
    void update(const LinkSet &links);

    // Calls visit(pair) for each pair of links whose boxes overlap and
    // which `filter` enables, until visit returns true; returns true then.
    template <class Visit>
    bool overlapping(const LinkPairs &filter, Visit &&visit) const {
        const size_t n = sorted_.size();
        for (size_t i = 0; i < n; ++i) {
            const Entry &x = sorted_[i];
            for (size_t j = i + 1; j < n && sorted_[j].box.lo[axis_] <= x.box.hi[axis_]; ++j) {
                const Entry &y = sorted_[j];
                if (!x.box.overlaps(y.box) || !filter.enabled(x.link, y.link)) continue;
                if (visit(x.link < y.link ? LinkPair{x.link, y.link} : LinkPair{y.link, x.link})) return true;
            }
        }
        return false;
    }

    // Every pair `filter` enables whose boxes are nearer than `cutoff`,
    // with that distance (a lower bound of the links' distance), nearest
    // first, into `out`.
    struct Candidate {
        LinkPair pair;
        double lower = 0.0;
    };
    void nearer_than(const LinkPairs &filter, double cutoff, std::vector<Candidate> &out) const;

    // The link's placed shapes: placed()[first(link)] .. + count(link).
    uint32_t first(uint32_t link) const { return ranges_[link].first; }
    uint32_t count(uint32_t link) const { return ranges_[link].count; }

private:
    struct Entry {
        Aabb box;
        uint32_t link;
    };
    struct Range {
        uint32_t first = 0, count = 0;
    };
    void choose_axis();

    std::vector<Entry> sorted_;   // by box.lo[axis_]
    std::vector<Range> ranges_;   // per link
    int axis_ = 0;
};

}  // namespace octoprox
