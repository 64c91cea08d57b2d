// The world's part of collision and distance answers (QueryContext): the
// same code for both engines, composed with the engine's octree answer.
#include "query/context.hpp"

#include <algorithm>
#include <limits>

namespace octoprox {

// The octree's contacts come first; the world's add up to max_contacts.
// An answer the octree settled (its first contact, for a query of at most
// one; a list already truncated) needs no object.
void QueryContext::collide_world(const LinkSet &links, const CollisionSettings &settings, CollisionAnswer &answer) {
    world_contacts_.clear();
    CollisionOutcome &o = answer.outcome;
    if (world_ == nullptr || o.truncated || (o.collided && settings.max_contacts <= 1)) return;
    WorldCollisionSettings s;
    s.max_contacts = settings.max_contacts, s.kept_before = contacts_.size(), s.penetration = settings.penetration;
    const WorldCollisionOutcome w = world_collider_.collide(*world_, links, s, world_contacts_);
    o.collided = o.collided || w.collided;
    o.truncated = o.truncated || w.truncated;
    o.narrow_tests += w.narrow_tests;
}

// The objects are searched below the octree's distance; per link, below
// each link's own (a link far from the nearest cell may be near an object).
void QueryContext::distance_world(const LinkSet &links, const DistanceSettings &settings, bool per_link,
                                  DistanceAnswer &answer) {
    if (world_ == nullptr) return;
    DistanceOutcome &o = answer.outcome;
    if (per_link && link_distances_.empty())
        link_distances_.assign(links.link_count(), std::numeric_limits<double>::infinity());
    // Each link's entry bounds its search among the objects (0: none).
    if (per_link && settings.link_cutoffs)
        for (size_t link = 0; link < link_distances_.size(); ++link)
            link_distances_[link] = std::min(link_distances_[link], std::max((*settings.link_cutoffs)[link], 0.0));
    const double bound = o.found && !per_link ? std::min(o.distance, settings.cutoff) : settings.cutoff;
    const WorldDistance w = world_collider_.distance(*world_, links, bound, settings.signed_distance,
                                                     per_link ? &link_distances_ : nullptr);
    o.narrow_tests += w.narrow_tests;
    if (!w.found || (o.found && !(w.distance < o.distance))) return;
    o.found = true;
    o.distance = w.distance, o.on_link = w.on_link, o.on_cell = w.on_object;
    o.link = w.link, o.shape = w.shape, o.attached = w.attached;
    answer.cell = CellSummary();
    answer.object = static_cast<int32_t>(w.object), answer.object_shape = w.object_shape;
}

}  // namespace octoprox
