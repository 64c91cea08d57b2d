// SelfChecker's distance half: opx_query_self_distance against the
// oracle's minimum, its reported pair, witnesses, cutoff and sign.
#include "oracle_self_check.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace oracle {
namespace {

constexpr double kExactTolerance = 1e-9;
constexpr double kCurvedTolerance = 1e-6;

opx_self_distance_result ask(opx_query *query, const opx_linkset *links, double cutoff, int32_t signed_distance,
                             bool &ok) {
    opx_self_distance_request request = OPX_SELF_DISTANCE_REQUEST_INIT;
    request.cutoff = cutoff, request.signed_distance = signed_distance;
    opx_self_distance_result result = OPX_SELF_DISTANCE_RESULT_INIT;
    ok = opx_query_self_distance(query, links, &request, &result) == OPX_OK;
    return result;
}

std::string number(double x) {
    std::ostringstream out;
    out.precision(17);
    out << x;
    return out.str();
}

}  // namespace

void SelfChecker::check_distance(opx_query *query, const opx_linkset *links, const SelfCase &c, bool collided) {
    ++distances_;
    const SelfMinimum m = self_minimum(*c.placed, *c.pairs, std::numeric_limits<double>::infinity());
    curved_minima_ += m.curved;
    const double tol = m.curved ? kCurvedTolerance : kExactTolerance;
    bool ok = false;
    const opx_self_distance_result r = ask(query, links, 0.0, 0, ok);
    if (!ok) return mismatch(c.label + ": opx_query_self_distance failed: " + opx_last_error());
    if (!m.found) {
        if (r.found || !std::isinf(r.distance)) mismatch(c.label + ": no checked pair, yet a distance is found");
        return;
    }
    if (!r.found) return mismatch(c.label + ": the oracle has pairs, the library found none");
    if (r.distance < m.distance.low - tol || r.distance > m.distance.high + tol)
        mismatch(c.label + ": distance " + number(r.distance) + ", the oracle's in [" + number(m.distance.low) + ", " +
                 number(m.distance.high) + "]");
    if (collided && r.collided != 1) mismatch(c.label + ": collided pairs, yet the distance says collided 0");
    if (!c.pairs->enabled(r.link_a, r.link_b) || r.link_a >= r.link_b)
        mismatch(c.label + ": the nearest pair names links " + std::to_string(r.link_a) + " and " +
                 std::to_string(r.link_b) + ", not a checked pair");
    check_witnesses(c, r);
    if (m.distance.low > 1e-6) {  // a cutoff below the minimum: not found, the cutoff returned
        const double cutoff = 0.5 * m.distance.low;
        const opx_self_distance_result cut = ask(query, links, cutoff, 0, ok);
        if (!ok || cut.found || cut.distance != cutoff) mismatch(c.label + ": cutoff below the minimum not honoured");
    }
    const opx_self_distance_result within = ask(query, links, 2.0 * m.distance.high + 1e-3, 0, ok);
    if (!ok || !within.found || std::abs(within.distance - r.distance) > tol)
        mismatch(c.label + ": a cutoff above the minimum changed the answer");
    const opx_self_distance_result sign = ask(query, links, 0.0, 1, ok);
    if (!ok) return mismatch(c.label + ": signed opx_query_self_distance failed: " + opx_last_error());
    if (collided && sign.distance > kExactTolerance) mismatch(c.label + ": touching pairs, signed distance > 0");
    if (m.distance.low > 2.0 * tol && std::abs(sign.distance - r.distance) > tol)
        mismatch(c.label + ": apart, signed " + number(sign.distance) + " differs from " + number(r.distance));
    if (r.distance <= 1e-9 && m.distance.high > 1e-9 + tol) ++undecided_;
}

// On each padded surface (apart), or a point both padded shapes hold (at 0).
void SelfChecker::check_witnesses(const SelfCase &c, const opx_self_distance_result &r) {
    const PlacedShape *a = find(c, r.link_a, r.shape_a), *b = find(c, r.link_b, r.shape_b);
    if (a == nullptr || b == nullptr) return mismatch(c.label + ": the nearest pair names an unknown shape");
    const bool curved = a->kind == OPX_SHAPE_CYLINDER || b->kind == OPX_SHAPE_CYLINDER;
    const double tol = curved ? kCurvedTolerance : kExactTolerance;
    const Vec3 on_a(r.point_on_a[0], r.point_on_a[1], r.point_on_a[2]);
    const Vec3 on_b(r.point_on_b[0], r.point_on_b[1], r.point_on_b[2]);
    if (std::abs((on_a - on_b).norm() - r.distance) > tol + 1e-12 * r.distance)
        mismatch(c.label + ": witnesses " + number((on_a - on_b).norm()) + " apart, distance " + number(r.distance));
    const Bracket pair = shape_pair_bracket(*a, *b);
    if (r.distance < pair.low - tol || r.distance > pair.high + tol)
        mismatch(c.label + ": the reported pair is " + number(pair.low) + " apart, not " + number(r.distance));
    const double da = point_core_distance(on_a, *a), db = point_core_distance(on_b, *b);
    const bool apart = r.distance > kExactTolerance;
    if ((apart && std::abs(da - a->inflation) > tol) || (!apart && da > a->inflation + tol))
        mismatch(c.label + ": point_on_a is " + number(da) + " from its core, inflation " + number(a->inflation));
    if ((apart && std::abs(db - b->inflation) > tol) || (!apart && db > b->inflation + tol))
        mismatch(c.label + ": point_on_b is " + number(db) + " from its core, inflation " + number(b->inflation));
}

}  // namespace oracle
