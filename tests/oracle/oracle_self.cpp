#include "oracle_self.hpp"

#include "oracle_self_fcl.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kPi = 3.14159265358979323846;
constexpr double kCurvedBand = 1e-6;  // GJK on a cylinder: ~1e-7 of the distance

bool curved(const PlacedShape &s) { return s.kind == OPX_SHAPE_CYLINDER; }

// The core as convex pieces (a cylinder made thinner and shorter by
// `shrink`).
std::vector<Piece> core_pieces(const PlacedShape &s, double shrink = 0.0) {
    switch (s.kind) {
    case OPX_SHAPE_SPHERE: return {point_piece(s.point)};
    case OPX_SHAPE_CAPSULE: return {segment_piece(s.segment)};
    case OPX_SHAPE_BOX: return {box_piece(s.box)};
    case OPX_SHAPE_CONVEX: return {polytope_piece(s.hull)};
    case OPX_SHAPE_CYLINDER: {
        Cylinder thinner = s.cylinder;
        thinner.radius -= shrink, thinner.length -= 2.0 * shrink;
        return {cylinder_piece(thinner)};
    }
    default: {
        std::vector<Piece> triangles;
        for (const Triangle &t : s.triangles) triangles.push_back(triangle_piece(t));
        return triangles;
    }
    }
}

// A cylinder as its prism of `sides` sides, inscribed or circumscribed;
// any other piece as it is.
Piece prism_of(const Piece &p, int sides, bool circumscribed) {
    if (p.kind != Piece::kCylinder) return p;
    const double rim = circumscribed ? p.cylinder.radius / std::cos(kPi / sides) : p.cylinder.radius;
    return polytope_piece(cylinder_prism(p.cylinder, sides, rim));
}

// Exact between polytopes; with a cylinder, FCL's agreed answer, else the
// prisms' bracket.
Bracket piece_bracket(const Piece &a, const Piece &b) {
    const bool a_round = a.kind == Piece::kCylinder, b_round = b.kind == Piece::kCylinder;
    if (!a_round && !b_round) {
        const double d = piece_distance(a, b);
        return {d, d};
    }
    double d = 0.0;
    if (fcl_cylinder_distance(a_round ? a : b, a_round ? b : a, d)) return {d, d};
    Bracket r;
    for (int sides : {64, 256}) {
        r.low = piece_distance(prism_of(a, sides, true), prism_of(b, sides, true));
        r.high = piece_distance(prism_of(a, sides, false), prism_of(b, sides, false));
        if (r.high - r.low <= kCurvedBand) break;
    }
    return r;
}

// The least distance over pairs of pieces, bracketed; pairs whose bounds
// are `bound` or more apart are skipped (the answer is then only known to
// be >= bound), and the search stops once a pair is surely within `enough`.
Bracket core_bracket(const PlacedShape &a, const PlacedShape &b, double bound, double enough, double shrink = 0.0) {
    const std::vector<Piece> pa = core_pieces(a, shrink), pb = core_pieces(b, shrink);
    Bracket best{kInfinity, kInfinity};
    for (const Piece &x : pa) {
        for (const Piece &y : pb) {
            if (bounds_distance(x, y) >= std::min(best.high, bound)) continue;
            const Bracket r = piece_bracket(x, y);
            best.low = std::min(best.low, r.low), best.high = std::min(best.high, r.high);
            if (best.high <= enough) return best;
        }
    }
    return best;
}

double bounds_gap(const PlacedShape &a, const PlacedShape &b) {
    return (a.bounds_min - b.bounds_max).cwiseMax(b.bounds_min - a.bounds_max).cwiseMax(0.0).norm();
}

// On core distances: touching when within the paddings plus 1e-9.  Cores
// that overlap with no padding are only sure to touch when a cylinder made
// thinner by twice the band still meets the other core.
Verdict decide(const PlacedShape &a, const PlacedShape &b) {
    const bool round = curved(a) || curved(b);
    const double band = round ? kCurvedBand : kExactAmbiguity;
    const double threshold = a.inflation + b.inflation + kTouchTolerance;
    const Bracket r = core_bracket(a, b, threshold + band + 1e-3, threshold - band);
    if (r.high <= threshold - band) return Verdict::kTouch;
    if (r.low > threshold + band) return Verdict::kClear;
    if (round && r.high <= 0.0 && core_bracket(a, b, 1.0, 0.0, 2.0 * band).high <= 0.0) return Verdict::kTouch;
    return Verdict::kAmbiguous;
}

// Every pair of shapes of two checked links, link_a < link_b.
template <class Visit>
void checked_pairs(const std::vector<PlacedShape> &placed, const PairMask &pairs, Visit &&visit) {
    for (const PlacedShape &a : placed)
        for (const PlacedShape &b : placed)
            if (a.link < b.link && pairs.enabled(a.link, b.link)) visit(a, b);
}

}  // namespace

Bracket shape_pair_bracket(const PlacedShape &a, const PlacedShape &b, double bound) {
    const double balls = a.inflation + b.inflation;
    const Bracket r = core_bracket(a, b, bound + balls, -1.0);
    return {std::max(0.0, r.low - balls), std::max(0.0, r.high - balls)};
}

std::vector<ShapePairVerdict> self_verdicts(const std::vector<PlacedShape> &placed, const PairMask &pairs) {
    std::vector<ShapePairVerdict> verdicts;
    checked_pairs(placed, pairs, [&](const PlacedShape &a, const PlacedShape &b) {
        if (bounds_gap(a, b) > kTouchTolerance + kCurvedBand) return;
        const Verdict v = decide(a, b);
        if (v != Verdict::kClear) verdicts.push_back({&a, &b, v});
    });
    return verdicts;
}

SelfMinimum self_minimum(const std::vector<PlacedShape> &placed, const PairMask &pairs, double cutoff) {
    struct Candidate {
        const PlacedShape *a, *b;
        double gap;
    };
    std::vector<Candidate> candidates;
    checked_pairs(placed, pairs, [&](const PlacedShape &a, const PlacedShape &b) {
        candidates.push_back({&a, &b, bounds_gap(a, b)});
    });
    std::sort(candidates.begin(), candidates.end(), [](const Candidate &x, const Candidate &y) { return x.gap < y.gap; });
    SelfMinimum m;
    for (const Candidate &c : candidates) {
        if (c.gap >= std::min(m.distance.high, cutoff)) break;
        const Bracket r = shape_pair_bracket(*c.a, *c.b, std::min(m.distance.high, cutoff));
        if (r.low < m.distance.high && (curved(*c.a) || curved(*c.b))) m.curved = true;
        m.distance.low = std::min(m.distance.low, r.low);
        m.distance.high = std::min(m.distance.high, r.high);
    }
    m.found = m.distance.low < cutoff;
    return m;
}

double point_core_distance(const Vec3 &p, const PlacedShape &shape) {
    if (shape.kind == OPX_SHAPE_CYLINDER) return point_cylinder_distance(p, shape.cylinder);
    double best = kInfinity;
    for (const Piece &piece : core_pieces(shape)) best = std::min(best, point_piece_distance(p, piece));
    return best;
}

}  // namespace oracle
