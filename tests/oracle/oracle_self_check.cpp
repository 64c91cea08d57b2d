#include "oracle_self_check.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <sstream>
#include <tuple>

namespace oracle {
namespace {

constexpr int kPrintedMismatches = 8;

using PairKey = std::tuple<uint32_t, uint32_t, uint32_t, uint32_t>;

PairKey key_of(const opx_self_contact &c) { return {c.link_a, c.shape_a, c.link_b, c.shape_b}; }
PairKey key_of(const ShapePairVerdict &v) { return {v.a->link, v.a->shape, v.b->link, v.b->shape}; }

std::string describe(const PairKey &k) {
    std::ostringstream out;
    out << "link " << std::get<0>(k) << " shape " << std::get<1>(k) << " / link " << std::get<2>(k) << " shape "
        << std::get<3>(k);
    return out.str();
}

std::string describe(const ShapePairVerdict &v) {
    std::ostringstream out;
    out.precision(17);
    out << describe(key_of(v)) << " (" << kind_name(v.a->kind) << " inflation " << v.a->inflation << ", "
        << kind_name(v.b->kind) << " inflation " << v.b->inflation << ")";
    return out.str();
}

}  // namespace

struct SelfChecker::Answer {
    opx_self_collision_result result = OPX_SELF_COLLISION_RESULT_INIT;
    std::vector<opx_self_contact> contacts;
};

SelfChecker::Answer SelfChecker::collide(opx_query *query, const opx_linkset *links, const SelfCase &c,
                                         uint32_t max_contacts) {
    Answer answer;
    opx_self_collision_request request = OPX_SELF_COLLISION_REQUEST_INIT;
    request.max_contacts = max_contacts;
    request.compute_penetration = max_contacts == UINT32_MAX ? 1 : 0;
    if (opx_query_self_collide(query, links, &request, &answer.result) != OPX_OK) {
        mismatch(c.label + ": opx_query_self_collide failed: " + opx_last_error());
        return answer;
    }
    for (uint64_t i = 0; i < answer.result.contact_count; ++i) {
        opx_self_contact contact = OPX_SELF_CONTACT_INIT;
        if (opx_query_get_self_contact(query, i, &contact) != OPX_OK) mismatch(c.label + ": " + opx_last_error());
        answer.contacts.push_back(contact);
    }
    return answer;
}

PairMask random_pairs(Rng &rng, opx_linkset *links, size_t count, double disabled) {
    PairMask mask(count);
    for (uint32_t a = 0; a < count; ++a) {
        for (uint32_t b = a + 1; b < count; ++b) {
            const bool enabled = !rng.chance(disabled);
            mask.set(a, b, enabled);
            require_ok(opx_linkset_set_pair_enabled(links, a, b, enabled ? 1 : 0), "opx_linkset_set_pair_enabled");
        }
    }
    return mask;
}

bool SelfChecker::check(opx_query *query, const opx_linkset *links, const SelfCase &c) {
    const uint64_t before = mismatches_;
    ++states_;
    const std::vector<ShapePairVerdict> oracle = self_verdicts(*c.placed, *c.pairs);
    size_t touching = 0;
    for (const ShapePairVerdict &v : oracle) touching += v.verdict == Verdict::kTouch;
    touching_pairs_ += touching, ambiguous_pairs_ += oracle.size() - touching;
    const Answer all = collide(query, links, c, UINT32_MAX);
    collided_ += all.result.collided;
    if (touching > 0 && !all.result.collided)
        mismatch(c.label + ": FALSE NEGATIVE: the oracle touches " + describe(oracle.front()) +
                 ", the library reports no self-collision");
    if (oracle.empty() && all.result.collided)
        mismatch(c.label + ": false positive: the library collides, the oracle touches nothing");
    if (all.result.truncated) mismatch(c.label + ": max_contacts=UINT32_MAX reported truncated=1");
    compare_contacts(c, oracle, all);
    for (uint32_t max : {0u, 1u}) {
        const Answer yes_no = collide(query, links, c, max);
        if (touching > 0 && !yes_no.result.collided)
            mismatch(c.label + ": FALSE NEGATIVE with max_contacts=" + std::to_string(max));
        if (oracle.empty() && yes_no.result.collided)
            mismatch(c.label + ": false positive with max_contacts=" + std::to_string(max));
    }
    check_limits(query, links, c, touching);
    check_distance(query, links, c, touching > 0);
    return mismatches_ == before;
}

void SelfChecker::compare_contacts(const SelfCase &c, const std::vector<ShapePairVerdict> &oracle,
                                   const Answer &all) {
    std::set<PairKey> reported;
    for (const opx_self_contact &contact : all.contacts) {
        const PairKey k = key_of(contact);
        if (!reported.insert(k).second) mismatch(c.label + ": duplicate contact " + describe(k));
        if (!(contact.depth >= 0.0) || (contact.depth > 0.0 && std::abs(std::hypot(contact.normal[0],
                                           contact.normal[1], contact.normal[2]) - 1.0) > 1e-9))
            mismatch(c.label + ": contact " + describe(k) + " has a bad depth or normal");
    }
    std::set<PairKey> allowed;
    for (const ShapePairVerdict &v : oracle) {
        allowed.insert(key_of(v));
        if (v.verdict == Verdict::kTouch && !reported.count(key_of(v)))
            mismatch(c.label + ": missed contact (false negative) " + describe(v));
    }
    for (const PairKey &k : reported)
        if (!allowed.count(k)) mismatch(c.label + ": library-only contact " + describe(k));
}

// max_contacts N (2 or more) below the total keeps N and says truncated.
void SelfChecker::check_limits(opx_query *query, const opx_linkset *links, const SelfCase &c, size_t touching) {
    const Answer one = collide(query, links, c, 1);
    if (one.result.contact_count > 1 || one.result.truncated)
        mismatch(c.label + ": max_contacts=1 gave " + std::to_string(one.result.contact_count) + " contacts");
    if (touching < 3) return;  // one contact stops the search: never truncated
    const uint32_t limit = static_cast<uint32_t>(touching - 1);
    const Answer some = collide(query, links, c, limit);
    if (some.result.contact_count != limit || !some.result.truncated)
        mismatch(c.label + ": max_contacts=" + std::to_string(limit) + " of " + std::to_string(touching) + " gave " +
                 std::to_string(some.result.contact_count) + " contacts, truncated " +
                 std::to_string(some.result.truncated));
}

const PlacedShape *SelfChecker::find(const SelfCase &c, uint32_t link, uint32_t shape) const {
    for (const PlacedShape &s : *c.placed)
        if (s.link == link && s.shape == shape) return &s;
    return nullptr;
}

void SelfChecker::mismatch(const std::string &message) {
    if (++mismatches_ <= kPrintedMismatches) std::printf("MISMATCH [%s] %s\n", name_.c_str(), message.c_str());
}

int SelfChecker::finish(double seconds) const {
    std::printf("%s: %llu states (%llu self-colliding), %llu touching shape pairs, %llu ambiguous, "
                "%llu distances (%llu with a cylinder nearest, %llu undecided), mismatches %llu; %.1f s\n",
                name_.c_str(), (unsigned long long)states_, (unsigned long long)collided_,
                (unsigned long long)touching_pairs_, (unsigned long long)ambiguous_pairs_,
                (unsigned long long)distances_, (unsigned long long)curved_minima_, (unsigned long long)undecided_,
                (unsigned long long)mismatches_, seconds);
    return mismatches_ == 0 ? 0 : 1;
}

}  // namespace oracle
