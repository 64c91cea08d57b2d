#include "query/self/link_boxes.hpp"

#include "base/avx2.hpp"
#include "narrowphase/narrow_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace octoprox {

uint64_t overlap_bits_portable(const BoxRows &rows, size_t row, size_t first, size_t count, uint64_t wanted) {
    uint64_t bits = 0;
    for (size_t k = 0; k < count; ++k) {
        if (((wanted >> k) & 1) == 0) continue;
        const size_t j = first + k;
        bool overlap = true;
        for (int axis = 0; axis < 3; ++axis)
            overlap &= (rows.lo[axis][j] <= rows.hi[axis][row]) & (rows.lo[axis][row] <= rows.hi[axis][j]);
        bits |= static_cast<uint64_t>(overlap) << k;
    }
    return bits;
}

uint64_t overlap_bits(const BoxRows &rows, size_t row, size_t first, size_t count, uint64_t wanted) {
    return cpu_has_avx2() ? overlap_bits_avx2(rows, row, first, count, wanted)
                          : overlap_bits_portable(rows, row, first, count, wanted);
}

// Which bodies have boxes: those of enabled links with shapes.
void LinkBoxes::lay_out(const LinkSet &links, bool with_attached) {
    const std::vector<PlacedShape> &placed = links.placed();
    const uint32_t link_count = static_cast<uint32_t>(links.link_count());
    ranges_.assign(link_count + links.attached_count(), Range());
    for (uint32_t i = 0; i < placed.size(); ++i) {
        const int32_t attached = placed[i].attached;
        Range &r = ranges_[attached < 0 ? placed[i].link : link_count + static_cast<uint32_t>(attached)];
        if (r.count++ == 0) r.first = i;
    }
    entries_.clear();
    const uint32_t bodies = with_attached ? static_cast<uint32_t>(ranges_.size()) : link_count;
    for (uint32_t body = 0; body < bodies; ++body) {
        const uint32_t link = body < link_count ? body : links.attached(body - link_count).link;
        if (ranges_[body].count == 0 || !links.link(link).enabled) continue;
        entries_.push_back(Entry{Aabb(), body, link});
    }
    const size_t padded = (entries_.size() + 3) / 4 * 4 + 4;
    for (int axis = 0; axis < 3; ++axis) {
        rows_.lo[axis].assign(padded, std::numeric_limits<double>::infinity());
        rows_.hi[axis].assign(padded, -std::numeric_limits<double>::infinity());
    }
    lay_out_enabled(links);
    identity_ = links.identity(), generation_ = links.generation(), with_attached_ = with_attached;
}

void LinkBoxes::lay_out_enabled(const LinkSet &links) {
    const BodyPairs filter(links, links.pairs());
    const size_t n = entries_.size();
    enabled_.clear();
    word_start_.assign(n, 0);
    for (size_t i = 0; i < n; ++i) {
        word_start_[i] = enabled_.size();
        for (size_t first = i + 1; first < n; first += 64) {
            uint64_t word = 0;
            for (size_t k = 0; k < 64 && first + k < n; ++k)
                if (filter.enabled(entries_[i].body, entries_[first + k].body)) word |= uint64_t{1} << k;
            enabled_.push_back(word);
        }
    }
}

void LinkBoxes::update(const LinkSet &links, bool with_attached) {
    if (identity_ != links.identity() || generation_ != links.generation() || with_attached_ != with_attached)
        lay_out(links, with_attached);
    const std::vector<PlacedShape> &placed = links.placed();
    for (size_t e = 0; e < entries_.size(); ++e) {
        Entry &entry = entries_[e];
        const Range &range = ranges_[entry.body];
        entry.box = Aabb();
        for (uint32_t k = 0; k < range.count; ++k) entry.box.grow(placed[range.first + k].box);
        // Shapes within the touch tolerance collide: boxes that far apart
        // must still overlap (their faces may differ by a rounding).
        entry.box.inflate(kTouchTolerance);
        for (int axis = 0; axis < 3; ++axis) {
            rows_.lo[axis][e] = entry.box.lo[axis];
            rows_.hi[axis][e] = entry.box.hi[axis];
        }
    }
}

void LinkBoxes::nearer_than(const BodyPairs &filter, double cutoff, std::vector<Candidate> &out) const {
    out.clear();
    for (size_t i = 0; i < entries_.size(); ++i) {
        for (size_t j = i + 1; j < entries_.size(); ++j) {
            const Entry &x = entries_[i], &y = entries_[j];
            if (!filter.enabled(x.body, y.body)) continue;
            const double lower = std::sqrt(x.box.squared_distance(y.box));
            if (lower >= cutoff) continue;
            out.push_back({ordered(x, y), lower});
        }
    }
    std::sort(out.begin(), out.end(), [](const Candidate &x, const Candidate &y) { return x.lower < y.lower; });
}

}  // namespace octoprox
