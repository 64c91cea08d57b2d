#include "query/world/world_collider.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "narrowphase/shape_pair.hpp"

#include <algorithm>
#include <cmath>

namespace octoprox {
namespace {

WorldContact contact_of(const PlacedShape &shape, const PlacedShape &object, bool penetration,
                        uint64_t &narrow_tests) {
    WorldContact c;
    c.link = shape.link, c.shape = shape.shape, c.attached = shape.attached;
    c.object = object.link, c.object_shape = object.shape;
    if (penetration) {
        const ShapePairPenetration p = shape_pair_penetration(shape, object, narrow_tests);
        c.depth = p.depth, c.normal = p.normal, c.position = 0.5 * (p.on_a + p.on_b);
    }
    return c;
}

// Signed and in contact (bound <= 0), a touching pair (distance 0) must
// still be found to be measured by its penetration, as against cells.
double search_limit(double bound, bool signed_distance) {
    return signed_distance ? std::max(bound, 1e-300) : bound;
}

}  // namespace

template <class Visit>
bool WorldCollider::overlapping(const WorldIndex &index, const PlacedShape &shape, Visit &&visit) {
    Aabb reach = shape.box;
    reach.inflate(kTouchTolerance);
    stack_.assign(1, index.tree.root());
    while (!stack_.empty()) {
        const AabbTreeNode &node = index.tree.node(stack_.back());
        stack_.pop_back();
        if (!node.box.overlaps(reach)) continue;
        if (node.is_leaf()) {
            if (visit(*index.shapes[node.item])) return true;
            continue;
        }
        stack_.push_back(node.right);
        stack_.push_back(node.left);
    }
    return false;
}

// The contact rules of collision against the map (ContactSink), over the
// contacts the octree kept and these together.
WorldCollisionOutcome WorldCollider::collide(const World &world, const LinkSet &links,
                                             const WorldCollisionSettings &settings,
                                             std::vector<WorldContact> &contacts) {
    contacts.clear();
    WorldCollisionOutcome out;
    const WorldIndex &index = world.index();
    if (index.tree.empty()) return out;
    size_t kept = settings.kept_before;
    auto keep = [&](const PlacedShape &shape, const PlacedShape &object) {
        if (!shapes_touch(shape, object, out.narrow_tests)) return false;
        out.collided = true;
        if (kept >= settings.max_contacts) {
            out.truncated = settings.max_contacts > 0;
            return true;
        }
        contacts.push_back(contact_of(shape, object, settings.penetration, out.narrow_tests));
        ++kept;
        return kept >= settings.max_contacts && settings.max_contacts <= 1;
    };
    for (const PlacedShape &shape : links.placed()) {
        if (shape.box.empty()) continue;  // a disabled link's
        if (overlapping(index, shape, [&](const PlacedShape &object) { return keep(shape, object); })) break;
    }
    return out;
}

bool WorldCollider::collides(const World &world, const LinkSet &links, uint64_t &narrow_tests) {
    WorldCollisionSettings yes_no;
    yes_no.max_contacts = 0;
    const WorldCollisionOutcome o = collide(world, links, yes_no, no_contacts_);
    narrow_tests += o.narrow_tests;
    return o.collided;
}

// Nearest boxes first (the farther child waits on the stack), each pruned
// by the best distance so far.
void WorldCollider::nearest(const WorldIndex &index, const PlacedShape &shape, bool signed_distance,
                            WorldDistance &best) {
    auto lower = [&](int32_t node) { return std::sqrt(index.tree.node(node).box.squared_distance(shape.box)); };
    stack_.assign(1, index.tree.root());
    while (!stack_.empty()) {
        const int32_t at = stack_.back();
        stack_.pop_back();
        if (lower(at) >= search_limit(best.distance, signed_distance)) continue;
        const AabbTreeNode &node = index.tree.node(at);
        if (!node.is_leaf()) {
            const bool left_first = lower(node.left) <= lower(node.right);
            stack_.push_back(left_first ? node.right : node.left);
            stack_.push_back(left_first ? node.left : node.right);
            continue;
        }
        const PlacedShape &object = *index.shapes[node.item];
        ShapePairDistance d;
        if (!shape_pair_distance(shape, object, search_limit(best.distance, signed_distance), d, best.narrow_tests))
            continue;
        if (signed_distance && d.distance <= 0.0) {
            const ShapePairPenetration p = shape_pair_penetration(shape, object, best.narrow_tests);
            d.distance = -p.depth, d.on_a = p.on_a, d.on_b = p.on_b;
        }
        if (!(d.distance < best.distance)) continue;
        best.found = true;
        best.distance = d.distance, best.on_link = d.on_a, best.on_object = d.on_b;
        best.link = shape.link, best.shape = shape.shape, best.attached = shape.attached;
        best.object = object.link, best.object_shape = object.shape;
    }
}

// A link set's placed shapes come link by link (LinkSet::placed()).
WorldDistance WorldCollider::distance(const World &world, const LinkSet &links, double bound, bool signed_distance,
                                      std::vector<double> *per_link) {
    WorldDistance best;
    best.distance = bound;
    const WorldIndex &index = world.index();
    const std::vector<PlacedShape> &placed = links.placed();
    for (size_t i = 0; i < placed.size() && !index.tree.empty();) {
        const uint32_t link = placed[i].link;
        WorldDistance mine;
        mine.distance = per_link == nullptr ? best.distance : std::min(bound, (*per_link)[link]);
        for (; i < placed.size() && placed[i].link == link; ++i)
            if (!placed[i].box.empty()) nearest(index, placed[i], signed_distance, mine);
        best.narrow_tests += mine.narrow_tests;
        if (!mine.found) continue;
        if (per_link != nullptr) (*per_link)[link] = mine.distance;
        if (mine.distance < best.distance) {
            mine.narrow_tests = best.narrow_tests;
            best = mine;
        }
    }
    if (!best.found) best.distance = std::numeric_limits<double>::infinity();
    return best;
}

}  // namespace octoprox
