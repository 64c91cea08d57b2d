#include "query/self/pair_sampling.hpp"

#include "query/self/self_collider.hpp"

#include <cmath>
#include <random>

namespace octoprox {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Where a joint's random value is drawn: within its limits; a continuous
// joint (or a revolute one without limits) over a full turn; a prismatic
// joint without limits stays at 0.
void sample_range(const Joint &joint, double &low, double &high) {
    low = high = 0.0;
    if (!joint.moves() || joint.mimic != kNoIndex) return;
    const bool turns = joint.type != JointType::kPrismatic;
    if (joint.has_limits && joint.type != JointType::kContinuous && std::isfinite(joint.lower) &&
        std::isfinite(joint.upper) && joint.lower <= joint.upper) {
        low = joint.lower, high = joint.upper;
    } else if (turns) {
        low = -kPi, high = kPi;
    }
}

// Poses `posed` (a copy of the link set) at one random configuration.
class Sampler {
public:
    Sampler(const JointTree &joints, const LinkSet &posed, uint64_t seed)
        : joints_(joints), random_(seed), values_(joints.joint_count()), poses_(posed.link_count()) {
        for (uint32_t i = 0; i < posed.link_count(); ++i) poses_[i] = posed.link(i).pose;
    }

    void next(LinkSet &posed) {
        for (uint32_t j = 0; j < joints_.joint_count(); ++j) {
            double low, high;
            sample_range(joints_.joint(j), low, high);
            values_[j] = low == high ? low : std::uniform_real_distribution<double>(low, high)(random_);
        }
        joints_.set_commanded(values_.data());
        joints_.update_positions();
        joints_.link_poses(Pose(), poses_);  // links past the tree keep their pose
        posed.set_poses(poses_);
    }

private:
    JointTree joints_;  // a copy: the caller's positions stay
    std::mt19937_64 random_;
    std::vector<double> values_;
    std::vector<Pose> poses_;
};

// Removes the touching pairs from `candidates`.
void remove_pairs(LinkPairs &candidates, const std::vector<LinkPair> &touching) {
    for (const LinkPair &p : touching) candidates.set_enabled(p.a, p.b, false);
}

// Keeps in `candidates` only the touching pairs.
void keep_pairs(LinkPairs &candidates, const std::vector<LinkPair> &touching) {
    LinkPairs kept;
    kept.resize(candidates.link_count());
    for (uint32_t a = 0; a < candidates.link_count(); ++a)
        for (uint32_t b = a + 1; b < candidates.link_count(); ++b) kept.set_enabled(a, b, false);
    for (const LinkPair &p : touching)
        if (candidates.enabled(p.a, p.b)) kept.set_enabled(p.a, p.b, true);
    candidates = kept;
}

// Every pair `candidates` still enables gets disabled in `links`.
uint32_t disable_remaining(const LinkPairs &candidates, LinkSet &links) {
    uint32_t disabled = 0;
    for (uint32_t a = 0; a < links.link_count(); ++a)
        for (uint32_t b = a + 1; b < links.link_count(); ++b)
            if (candidates.enabled(a, b) && links.pairs().enabled(a, b)) links.set_pair_enabled(a, b, false), ++disabled;
    return disabled;
}

// The enabled pairs of two links that both have shapes (the others never touch).
LinkPairs testable_pairs(const LinkSet &links) {
    LinkPairs pairs = links.pairs();
    for (uint32_t a = 0; a < links.link_count(); ++a)
        for (uint32_t b = a + 1; b < links.link_count(); ++b)
            if (links.link(a).shapes.empty() || links.link(b).shapes.empty()) pairs.set_enabled(a, b, false);
    return pairs;
}

// The testable pairs touching at the copy's current poses, disabled.
uint32_t disable_touching_now(const LinkSet &posed, LinkSet &links, SelfCollider &collider) {
    std::vector<LinkPair> touching;
    collider.touching_pairs(posed, testable_pairs(links), touching);
    for (const LinkPair &p : touching) links.set_pair_enabled(p.a, p.b, false);
    return static_cast<uint32_t>(touching.size());
}

}  // namespace

PairSamplingOutcome disable_never_colliding_pairs(LinkSet &links, const JointTree &joints,
                                                  const PairSamplingSettings &settings) {
    LinkSet posed(links);
    for (uint32_t link = 0; link < posed.link_count(); ++link) posed.set_link_enabled(link, true);
    SelfCollider collider;
    PairSamplingOutcome outcome;
    if (settings.also_now) outcome.now = disable_touching_now(posed, links, collider);
    Sampler sampler(joints, posed, settings.seed);
    LinkPairs never = testable_pairs(links), always = never;
    std::vector<LinkPair> touching;
    for (uint32_t s = 0; s < settings.samples; ++s) {
        sampler.next(posed);
        collider.touching_pairs(posed, never, touching);
        remove_pairs(never, touching);
        if (!settings.also_always) continue;
        collider.touching_pairs(posed, always, touching);
        keep_pairs(always, touching);
    }
    outcome.never = disable_remaining(never, links);
    if (settings.also_always && settings.samples > 0) outcome.always = disable_remaining(always, links);
    return outcome;
}

}  // namespace octoprox
