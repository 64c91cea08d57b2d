#include "query/self/self_collider.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "narrowphase/shape_pair.hpp"

namespace octoprox {
namespace {

// Shapes whose boxes are within the touch tolerance may touch.
bool boxes_within_touch(const Aabb &a, const Aabb &b) {
    Aabb grown = a;
    grown.inflate(kTouchTolerance);
    return grown.overlaps(b);
}

SelfContact contact_of(const PlacedShape &a, const PlacedShape &b, bool penetration, uint64_t &narrow_tests) {
    SelfContact c;
    c.link_a = a.link, c.shape_a = a.shape, c.link_b = b.link, c.shape_b = b.shape;
    c.attached_a = a.attached, c.attached_b = b.attached;
    if (penetration) {
        const ShapePairPenetration p = shape_pair_penetration(a, b, narrow_tests);
        c.depth = p.depth, c.normal = p.normal, c.position = 0.5 * (p.on_a + p.on_b);
    }
    return c;
}

}  // namespace

template <class Visit>
bool SelfCollider::shape_pairs(const LinkSet &links, const LinkPair &pair, Visit &&visit) const {
    const std::vector<PlacedShape> &placed = links.placed();
    const uint32_t first_a = boxes_.first(pair.a), count_a = boxes_.count(pair.a);
    const uint32_t first_b = boxes_.first(pair.b), count_b = boxes_.count(pair.b);
    for (uint32_t i = first_a; i < first_a + count_a; ++i)
        for (uint32_t j = first_b; j < first_b + count_b; ++j)
            if (boxes_within_touch(placed[i].box, placed[j].box) && visit(placed[i], placed[j])) return true;
    return false;
}

bool SelfCollider::links_touch(const LinkSet &links, const LinkPair &pair, uint64_t &narrow_tests) const {
    return shape_pairs(links, pair, [&](const PlacedShape &a, const PlacedShape &b) {
        return shapes_touch(a, b, narrow_tests);
    });
}

bool SelfCollider::collides(const LinkSet &links) {
    boxes_.update(links);
    uint64_t narrow_tests = 0;
    return boxes_.overlapping_enabled([&](const LinkPair &pair) { return links_touch(links, pair, narrow_tests); });
}

// The contact rules of collision against the map (ContactSink): with at
// most one contact wanted the first touching pair settles the answer; a
// touching pair beyond max_contacts (> 0) marks the list truncated.
SelfCollisionOutcome SelfCollider::collide(const LinkSet &links, const SelfCollisionSettings &settings,
                                           std::vector<SelfContact> &contacts) {
    contacts.clear();
    SelfCollisionOutcome out;
    boxes_.update(links);
    auto keep = [&](const PlacedShape &a, const PlacedShape &b) {
        if (!shapes_touch(a, b, out.narrow_tests)) return false;
        out.collided = true;
        if (contacts.size() >= settings.max_contacts) {
            out.truncated = settings.max_contacts > 0;
            return true;
        }
        contacts.push_back(contact_of(a, b, settings.penetration, out.narrow_tests));
        return contacts.size() >= settings.max_contacts && settings.max_contacts <= 1;
    };
    boxes_.overlapping_enabled([&](const LinkPair &pair) {
        ++out.link_pairs;
        return shape_pairs(links, pair, keep);
    });
    return out;
}

void SelfCollider::touching_pairs(const LinkSet &links, const LinkPairs &filter, std::vector<LinkPair> &out) {
    out.clear();
    boxes_.update(links, false);
    uint64_t narrow_tests = 0;
    boxes_.overlapping(BodyPairs(links, filter), [&](const LinkPair &pair) {
        if (links_touch(links, pair, narrow_tests)) out.push_back(pair);
        return false;
    });
}

}  // namespace octoprox
