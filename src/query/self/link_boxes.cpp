#include "query/self/link_boxes.hpp"

#include "narrowphase/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {

void LinkBoxes::update(const LinkSet &links) {
    const std::vector<PlacedShape> &placed = links.placed();
    ranges_.assign(links.link_count(), Range());
    for (uint32_t i = 0; i < placed.size(); ++i) {
        Range &r = ranges_[placed[i].link];
        if (r.count++ == 0) r.first = i;
    }
    sorted_.clear();
    for (uint32_t link = 0; link < links.link_count(); ++link) {
        if (ranges_[link].count == 0 || !links.link(link).enabled) continue;
        Entry e{Aabb(), link};
        for (uint32_t k = 0; k < ranges_[link].count; ++k) e.box.grow(placed[ranges_[link].first + k].box);
        // Shapes within the touch tolerance collide: boxes that far apart
        // must still overlap (their faces may differ by a rounding).
        e.box.inflate(kTouchTolerance);
        sorted_.push_back(e);
    }
    choose_axis();
    std::sort(sorted_.begin(), sorted_.end(),
              [&](const Entry &x, const Entry &y) { return x.box.lo[axis_] < y.box.lo[axis_]; });
}

// The axis along which the box centres spread most: the sweep then sees
// the fewest boxes overlapping the current one on its axis alone.
void LinkBoxes::choose_axis() {
    if (sorted_.empty()) return;
    Vec3 sum = Vec3::Zero(), squares = Vec3::Zero();
    for (const Entry &e : sorted_) {
        const Vec3 c = e.box.center();
        sum += c, squares += c.cwiseProduct(c);
    }
    const double n = static_cast<double>(sorted_.size());
    const Vec3 spread = squares / n - (sum / n).cwiseProduct(sum / n);
    spread.maxCoeff(&axis_);
}

void LinkBoxes::nearer_than(const LinkPairs &filter, double cutoff, std::vector<Candidate> &out) const {
    out.clear();
    for (size_t i = 0; i < sorted_.size(); ++i) {
        for (size_t j = i + 1; j < sorted_.size(); ++j) {
            const Entry &x = sorted_[i], &y = sorted_[j];
            if (!filter.enabled(x.link, y.link)) continue;
            const double lower = std::sqrt(x.box.squared_distance(y.box));
            if (lower >= cutoff) continue;
            const LinkPair pair = x.link < y.link ? LinkPair{x.link, y.link} : LinkPair{y.link, x.link};
            out.push_back({pair, lower});
        }
    }
    std::sort(out.begin(), out.end(), [](const Candidate &x, const Candidate &y) { return x.lower < y.lower; });
}

}  // namespace octoprox
