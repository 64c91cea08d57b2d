// The broad phase of self-collision: one box per body (a link's own padded
// shapes, or an object attached to a link) and, for collision, the pairs
// of bodies whose boxes overlap: each body's box tested against those of
// the bodies after it, four at a time (AVX2 where the processor has it),
// as bits without a branch; for the set's own pairs, only the lanes of
// pairs it enables (the PR2's SRDF disables two pairs in three).  For
// distance, every pair with the distance of its boxes.  A set of n bodies
// costs at most n^2 / 2 box tests in lanes, a few hundred nanoseconds for
// a PR2's 59, where a sort and sweep pays a sort and a mispredicted
// branch per pair the sweep meets.
//
// Bodies are numbered links first (body l is link l), then attached
// objects (body link_count + i is attached object i).
#pragma once

#include "robot/linkset.hpp"

#include <algorithm>
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

// The entries' boxes by coordinate, each column padded with empty boxes
// (which overlap nothing) to a multiple of 4 plus 4, so four lanes may be
// read from any entry.
struct BoxRows {
    std::vector<double> lo[3], hi[3];
};

// Bit k set when bit k of `wanted` is and the box of entry `first + k`
// (k < count <= 64) overlaps that of entry `row`; four entries with no
// wanted bit cost no test.  The AVX2 loop (where cpu_has_avx2(),
// base/avx2.hpp) and the portable one give the same bits.
constexpr uint64_t kEveryEntry = ~uint64_t{0};
uint64_t overlap_bits(const BoxRows &rows, size_t row, size_t first, size_t count, uint64_t wanted = kEveryEntry);
uint64_t overlap_bits_portable(const BoxRows &rows, size_t row, size_t first, size_t count,
                               uint64_t wanted = kEveryEntry);
uint64_t overlap_bits_avx2(const BoxRows &rows, size_t row, size_t first, size_t count,
                           uint64_t wanted = kEveryEntry);

class LinkBoxes {
public:
    // The boxes of the bodies of enabled links that have shapes (attached
    // objects only `with_attached`), at the set's poses, grown by the touch
    // tolerance.  Which bodies those are is worked out again only when the
    // set is another one or changed in more than its poses.
    void update(const LinkSet &links, bool with_attached = true);

    // Calls visit(pair) for each pair of bodies whose boxes overlap and
    // which `filter` enables, until visit returns true; returns true then.
    // Pairs come by their first body, then their second, in body order.
    template <class Visit>
    bool overlapping(const BodyPairs &filter, Visit &&visit) const {
        return overlapping_wanted(nullptr, [&](const LinkPair &pair) {
            return filter.enabled(pair.a, pair.b) && visit(pair);
        });
    }
    // The same for the pairs the set itself enables (BodyPairs of its own
    // link pairs), which update() laid out as bits: only the boxes of
    // enabled pairs are tested.
    template <class Visit>
    bool overlapping_enabled(Visit &&visit) const {
        return overlapping_wanted(enabled_.data(), visit);
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
    void lay_out(const LinkSet &links, bool with_attached);
    void lay_out_enabled(const LinkSet &links);
    // Entry i's words of wanted bits for the entries after it, 64 a word,
    // at enabled_[word_start_[i]]...; null: every entry.
    template <class Visit>
    bool overlapping_wanted(const uint64_t *wanted, Visit &&visit) const {
        const size_t n = entries_.size();
        for (size_t i = 0; i + 1 < n; ++i) {
            const uint64_t *words = wanted != nullptr ? wanted + word_start_[i] : nullptr;
            for (size_t first = i + 1; first < n; first += 64, words += words != nullptr) {
                const uint64_t want = words != nullptr ? *words : kEveryEntry;
                if (want == 0) continue;
                const size_t count = std::min<size_t>(64, n - first);
                for (uint64_t bits = overlap_bits(rows_, i, first, count, want); bits != 0; bits &= bits - 1) {
                    const Entry &x = entries_[i], &y = entries_[first + static_cast<size_t>(__builtin_ctzll(bits))];
                    if (visit(ordered(x, y))) return true;
                }
            }
        }
        return false;
    }

    std::vector<Entry> entries_;  // by body
    std::vector<Range> ranges_;   // per body
    BoxRows rows_;                // the entries' boxes
    std::vector<uint64_t> enabled_;    // bits of the pairs the set enables (overlapping_wanted)
    std::vector<size_t> word_start_;   // per entry, its first word in enabled_
    // The set and state the entries were laid out for; identity 0: none
    // yet (link sets' identities start at 1).
    uint64_t identity_ = 0, generation_ = 0;
    bool with_attached_ = false;
};

}  // namespace octoprox
