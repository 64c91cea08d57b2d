#include "query/self/link_boxes.hpp"

#include "narrowphase/narrow_phase.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {

void LinkBoxes::update(const LinkSet &links, bool with_attached) {
    const std::vector<PlacedShape> &placed = links.placed();
    const uint32_t link_count = static_cast<uint32_t>(links.link_count());
    ranges_.assign(link_count + links.attached_count(), Range());
    for (uint32_t i = 0; i < placed.size(); ++i) {
        const int32_t attached = placed[i].attached;
        Range &r = ranges_[attached < 0 ? placed[i].link : link_count + static_cast<uint32_t>(attached)];
        if (r.count++ == 0) r.first = i;
    }
    sorted_.clear();
    const uint32_t bodies = with_attached ? static_cast<uint32_t>(ranges_.size()) : link_count;
    for (uint32_t body = 0; body < bodies; ++body) {
        const uint32_t link = body < link_count ? body : links.attached(body - link_count).link;
        if (ranges_[body].count == 0 || !links.link(link).enabled) continue;
        Entry e{Aabb(), body, link};
        for (uint32_t k = 0; k < ranges_[body].count; ++k) e.box.grow(placed[ranges_[body].first + k].box);
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

void LinkBoxes::nearer_than(const BodyPairs &filter, double cutoff, std::vector<Candidate> &out) const {
    out.clear();
    for (size_t i = 0; i < sorted_.size(); ++i) {
        for (size_t j = i + 1; j < sorted_.size(); ++j) {
            const Entry &x = sorted_[i], &y = sorted_[j];
            if (!filter.enabled(x.body, y.body)) continue;
            const double lower = std::sqrt(x.box.squared_distance(y.box));
            if (lower >= cutoff) continue;
            out.push_back({ordered(x, y), lower});
        }
    }
    std::sort(out.begin(), out.end(), [](const Candidate &x, const Candidate &y) { return x.lower < y.lower; });
}

}  // namespace octoprox
