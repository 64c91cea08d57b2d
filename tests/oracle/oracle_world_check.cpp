// WorldChecker's collision half: opx_query_collide with objects only,
// against the touching pairs of the oracle.
#include "oracle_world_check.hpp"

#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>
#include <tuple>

namespace oracle {
namespace {

constexpr int kPrintedMismatches = 8;

// (link, shape, object, object shape).
using ContactKey = std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>;

std::string describe(const ContactKey &k) {
    std::ostringstream out;
    out << "link " << std::get<0>(k) << " shape " << std::get<1>(k) << " / object " << std::get<2>(k) << " shape "
        << std::get<3>(k);
    return out.str();
}

}  // namespace

PairMask link_object_pairs(uint32_t robot_links, uint32_t objects) {
    PairMask mask(robot_links + objects);
    for (uint32_t a = 0; a < robot_links + objects; ++a)
        for (uint32_t b = a + 1; b < robot_links + objects; ++b) mask.set(a, b, a < robot_links && b >= robot_links);
    return mask;
}

WorldChecker::Answer WorldChecker::collide(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                           const WorldCase &c, uint32_t max_contacts) {
    Answer answer;
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.max_contacts = max_contacts;
    request.compute_penetration = max_contacts == UINT32_MAX ? 1 : 0;
    if (opx_query_collide(query, tree, links, &request, &answer.result) != OPX_OK) {
        mismatch(c.label + ": opx_query_collide failed: " + opx_last_error());
        return answer;
    }
    for (uint64_t i = 0; i < answer.result.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        if (opx_query_get_contact(query, i, &contact) != OPX_OK) mismatch(c.label + ": " + opx_last_error());
        answer.contacts.push_back(contact);
    }
    return answer;
}

void WorldChecker::check_objects(opx_query *query, const opx_linkset *links, const WorldCase &c) {
    ++states_;
    const std::vector<ShapePairVerdict> oracle = self_verdicts(*c.placed, *c.pairs);
    size_t touching = 0;
    for (const ShapePairVerdict &v : oracle) touching += v.verdict == Verdict::kTouch;
    touching_pairs_ += touching, ambiguous_pairs_ += oracle.size() - touching;
    const Answer all = collide(query, nullptr, links, c, UINT32_MAX);
    collided_ += all.result.collided;
    if (touching > 0 && !all.result.collided)
        mismatch(c.label + ": FALSE NEGATIVE: the oracle has " + std::to_string(touching) +
                 " touching pairs, the library no collision");
    if (oracle.empty() && all.result.collided)
        mismatch(c.label + ": false positive: the library collides, the oracle touches nothing");
    if (all.result.truncated) mismatch(c.label + ": max_contacts=UINT32_MAX reported truncated=1");
    compare_contacts(c, oracle, all);
    for (uint32_t max : {0u, 1u}) {
        const Answer yes_no = collide(query, nullptr, links, c, max);
        if ((touching > 0 && !yes_no.result.collided) || (oracle.empty() && yes_no.result.collided))
            mismatch(c.label + ": collided " + std::to_string(yes_no.result.collided) + " with max_contacts=" +
                     std::to_string(max));
    }
    check_limits(query, links, c, touching);
    check_distance(query, links, c, touching > 0);
    check_per_link(query, links, c);
}

void WorldChecker::compare_contacts(const WorldCase &c, const std::vector<ShapePairVerdict> &oracle,
                                    const Answer &all) {
    std::set<ContactKey> reported;
    for (const opx_contact &contact : all.contacts) {
        if (contact.object < 0) {
            mismatch(c.label + ": a cell contact without an octree");
            continue;
        }
        const ContactKey k{contact.link, contact.shape, static_cast<uint32_t>(contact.object), contact.object_shape};
        if (!reported.insert(k).second) mismatch(c.label + ": duplicate contact " + describe(k));
        const double n = std::hypot(contact.normal[0], contact.normal[1], contact.normal[2]);
        if (!(contact.depth >= 0.0) || (contact.depth > 0.0 && std::abs(n - 1.0) > 1e-9))
            mismatch(c.label + ": contact " + describe(k) + " has a bad depth or normal");
        if (contact.cell_size != 0.0 || contact.cell_probability != 0.0)
            mismatch(c.label + ": object contact " + describe(k) + " has cell fields");
    }
    std::set<ContactKey> allowed;
    for (const ShapePairVerdict &v : oracle) {
        const ContactKey k{v.a->link, v.a->shape, v.b->link - c.robot_links, v.b->shape};
        allowed.insert(k);
        if (v.verdict == Verdict::kTouch && !reported.count(k)) mismatch(c.label + ": missed contact " + describe(k));
    }
    for (const ContactKey &k : reported)
        if (!allowed.count(k)) mismatch(c.label + ": library-only contact " + describe(k));
}

// max_contacts N (2 or more) below the total keeps N and says truncated.
void WorldChecker::check_limits(opx_query *query, const opx_linkset *links, const WorldCase &c, size_t touching) {
    const Answer one = collide(query, nullptr, links, c, 1);
    if (one.result.contact_count > 1 || one.result.truncated)
        mismatch(c.label + ": max_contacts=1 gave " + std::to_string(one.result.contact_count) + " contacts");
    if (touching < 3) return;
    const uint32_t limit = static_cast<uint32_t>(touching - 1);
    const Answer some = collide(query, nullptr, links, c, limit);
    if (some.result.contact_count != limit || !some.result.truncated)
        mismatch(c.label + ": max_contacts=" + std::to_string(limit) + " of " + std::to_string(touching) + " gave " +
                 std::to_string(some.result.contact_count) + " contacts, truncated " +
                 std::to_string(some.result.truncated));
}

const PlacedShape *WorldChecker::find(const WorldCase &c, uint32_t link, uint32_t shape) const {
    for (const PlacedShape &s : *c.placed)
        if (s.link == link && s.shape == shape) return &s;
    return nullptr;
}

void WorldChecker::mismatch(const std::string &message) {
    if (++mismatches_ <= kPrintedMismatches) std::printf("MISMATCH [%s] %s\n", name_.c_str(), message.c_str());
}

int WorldChecker::finish(double seconds) const {
    std::printf("%s: %llu states (%llu colliding), %llu touching pairs, %llu ambiguous, %llu distances (%llu with "
                "a cylinder nearest), %llu states beside a map (%llu with an object nearest), mismatches %llu; "
                "%.1f s\n",
                name_.c_str(), (unsigned long long)states_, (unsigned long long)collided_,
                (unsigned long long)touching_pairs_, (unsigned long long)ambiguous_pairs_,
                (unsigned long long)distances_, (unsigned long long)curved_minima_, (unsigned long long)map_states_,
                (unsigned long long)map_object_nearest_, (unsigned long long)mismatches_, seconds);
    return mismatches_ == 0 ? 0 : 1;
}

}  // namespace oracle
