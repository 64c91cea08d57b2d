// Self-distance: the link pairs nearest first by their boxes, each measured
// shape pair by shape pair under the best distance so far, until the next
// pair's boxes lie beyond it.
#include "query/self/self_collider.hpp"

#include "narrowphase/shape_pair.hpp"

#include <cmath>
#include <limits>

namespace octoprox {

void SelfCollider::measure_pair(const LinkSet &links, const LinkPair &pair, SelfDistanceOutcome &best) const {
    const std::vector<PlacedShape> &placed = links.placed();
    const uint32_t first_a = boxes_.first(pair.a), first_b = boxes_.first(pair.b);
    for (uint32_t i = first_a; i < first_a + boxes_.count(pair.a); ++i) {
        for (uint32_t j = first_b; j < first_b + boxes_.count(pair.b); ++j) {
            const PlacedShape &a = placed[i], &b = placed[j];
            const double bound = best.distance;  // the cutoff until a pair is found
            if (std::sqrt(a.box.squared_distance(b.box)) >= bound) continue;
            ShapePairDistance d;
            if (!shape_pair_distance(a, b, bound, d, best.narrow_tests)) continue;
            best.found = true;
            best.distance = d.distance, best.on_a = d.on_a, best.on_b = d.on_b;
            best.link_a = a.link, best.shape_a = a.shape, best.link_b = b.link, best.shape_b = b.shape;
            best.attached_a = a.attached, best.attached_b = b.attached;
            if (d.distance <= 0.0) return;
        }
    }
}

// Signed: the deepest of the touching shape pairs, measured by penetration.
void SelfCollider::deepest_overlap(const LinkSet &links, SelfDistanceOutcome &best) {
    SelfCollisionSettings all;
    all.max_contacts = UINT32_MAX, all.penetration = true;
    const SelfCollisionOutcome o = collide(links, all, overlap_scratch_);
    best.narrow_tests += o.narrow_tests;
    const SelfContact *deepest = nullptr;
    for (const SelfContact &c : overlap_scratch_)
        if (deepest == nullptr || c.depth > deepest->depth) deepest = &c;
    if (deepest == nullptr) return;
    best.distance = -deepest->depth;
    best.on_a = deepest->position + 0.5 * deepest->depth * deepest->normal;
    best.on_b = deepest->position - 0.5 * deepest->depth * deepest->normal;
    best.link_a = deepest->link_a, best.shape_a = deepest->shape_a;
    best.link_b = deepest->link_b, best.shape_b = deepest->shape_b;
    best.attached_a = deepest->attached_a, best.attached_b = deepest->attached_b;
}

SelfDistanceOutcome SelfCollider::distance(const LinkSet &links, const SelfDistanceSettings &settings) {
    SelfDistanceOutcome best;
    best.distance = settings.cutoff;
    boxes_.update(links);
    boxes_.nearer_than(BodyPairs(links, links.pairs()), settings.cutoff, candidates_);
    const uint32_t link_count = static_cast<uint32_t>(links.link_count());
    const auto link_of = [&](uint32_t body) {
        return body < link_count ? body : links.attached(body - link_count).link;
    };
    for (const LinkBoxes::Candidate &c : candidates_) {
        if (c.lower >= best.distance) break;
        if (settings.moving_links != nullptr && !(*settings.moving_links)[link_of(c.pair.a)] &&
            !(*settings.moving_links)[link_of(c.pair.b)])
            continue;
        ++best.link_pairs;
        measure_pair(links, c.pair, best);
        if (best.found && best.distance <= 0.0) break;
    }
    if (settings.signed_distance && best.found && best.distance <= 0.0) deepest_overlap(links, best);
    if (!best.found) best.distance = std::numeric_limits<double>::infinity();
    return best;
}

}  // namespace octoprox
