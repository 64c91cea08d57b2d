// WorldChecker's distance half (objects only: the oracle's minimum, the
// pair, witnesses, cutoff, sign, per link) and its checks beside an octree
// (union and minimum of the two parts, both engines alike).
#include "oracle_world_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>
#include <vector>

namespace oracle {
namespace {

constexpr double kExactTolerance = 1e-9;
constexpr double kCurvedTolerance = 1e-6;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

opx_distance_result ask(opx_query *query, const opx_octree *tree, const opx_linkset *links, double cutoff,
                        int32_t signed_distance, int32_t per_link, bool &ok) {
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.cutoff = cutoff, request.signed_distance = signed_distance, request.per_link = per_link;
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    ok = opx_query_distance(query, tree, links, &request, &result) == OPX_OK;
    return result;
}

std::vector<double> link_distances(const opx_query *query) {
    size_t count = 0;
    opx_query_get_link_distances(query, nullptr, 0, &count);
    std::vector<double> out(count);
    if (count > 0 && opx_query_get_link_distances(query, out.data(), count, &count) != OPX_OK) out.clear();
    return out;
}

// A mesh with a zero-area (collinear) triangle: GJK's witness on such a
// triangle may lie off it, the distance being right; its witnesses are
// only checked to be `distance` apart.
bool has_flat_triangle(const PlacedShape &s) {
    for (const Triangle &t : s.triangles)
        if ((t.b - t.a).cross(t.c - t.a).norm() <= 1e-12 * (t.b - t.a).squaredNorm() + 1e-300) return true;
    return false;
}

double value_of(const opx_distance_result &r) { return r.found ? r.distance : kInfinity; }

std::string number(double x) {
    std::ostringstream out;
    out.precision(17);
    out << x;
    return out.str();
}

}  // namespace

void WorldChecker::check_distance(opx_query *query, const opx_linkset *links, const WorldCase &c, bool collided) {
    ++distances_;
    const SelfMinimum m = self_minimum(*c.placed, *c.pairs, kInfinity);
    curved_minima_ += m.curved;
    const double tol = m.curved ? kCurvedTolerance : kExactTolerance;
    bool ok = false;
    const opx_distance_result r = ask(query, nullptr, links, 0.0, 0, 0, ok);
    if (!ok) return mismatch(c.label + ": opx_query_distance failed: " + opx_last_error());
    if (!m.found) {
        if (r.found || r.object != -1) mismatch(c.label + ": no pair, yet a distance is found");
        return;
    }
    if (!r.found || r.object < 0) return mismatch(c.label + ": the oracle has pairs, the library found no object");
    if (r.distance < m.distance.low - tol || r.distance > m.distance.high + tol)
        mismatch(c.label + ": distance " + number(r.distance) + ", the oracle's in [" + number(m.distance.low) + ", " +
                 number(m.distance.high) + "]");
    if (collided && r.collided != 1) mismatch(c.label + ": touching pairs, yet the distance says collided 0");
    check_witnesses(c, r);
    if (m.distance.low > 1e-6) {
        const double cutoff = 0.5 * m.distance.low;
        const opx_distance_result cut = ask(query, nullptr, links, cutoff, 0, 0, ok);
        if (!ok || cut.found || cut.distance != cutoff || cut.object != -1)
            mismatch(c.label + ": a cutoff below the minimum not honoured");
    }
    const opx_distance_result sign = ask(query, nullptr, links, 0.0, 1, 0, ok);
    if (!ok) return mismatch(c.label + ": signed opx_query_distance failed: " + opx_last_error());
    if (collided && sign.distance > kExactTolerance) mismatch(c.label + ": touching pairs, signed distance > 0");
    if (m.distance.low > 2.0 * tol && std::abs(sign.distance - r.distance) > tol)
        mismatch(c.label + ": apart, signed " + number(sign.distance) + " differs from " + number(r.distance));
}

// Each link's minimum: the oracle over that link's pairs alone.
void WorldChecker::check_per_link(opx_query *query, const opx_linkset *links, const WorldCase &c) {
    bool ok = false;
    ask(query, nullptr, links, 0.0, 0, 1, ok);
    const std::vector<double> got = link_distances(query);
    if (!ok || got.size() != c.robot_links) return mismatch(c.label + ": per-link distances missing");
    const uint32_t total = static_cast<uint32_t>(c.pairs->links());
    for (uint32_t link = 0; link < c.robot_links; ++link) {
        PairMask mine(total);
        for (uint32_t a = 0; a < total; ++a)
            for (uint32_t b = a + 1; b < total; ++b) mine.set(a, b, a == link && c.pairs->enabled(a, b));
        const SelfMinimum m = self_minimum(*c.placed, mine, kInfinity);
        const double tol = m.curved ? kCurvedTolerance : kExactTolerance;
        const bool within = m.found ? got[link] >= m.distance.low - tol && got[link] <= m.distance.high + tol
                                    : std::isinf(got[link]);
        if (!within)
            mismatch(c.label + ": link " + std::to_string(link) + " distance " + number(got[link]) + ", the oracle's [" +
                     number(m.distance.low) + ", " + number(m.distance.high) + "]");
    }
}

// On each padded surface (apart), or a point both padded shapes hold (at 0).
void WorldChecker::check_witnesses(const WorldCase &c, const opx_distance_result &r) {
    const PlacedShape *a = find(c, r.link, r.shape);
    const PlacedShape *b = find(c, c.robot_links + static_cast<uint32_t>(r.object), r.object_shape);
    if (a == nullptr || b == nullptr) return mismatch(c.label + ": the nearest pair names an unknown shape");
    const bool curved = a->kind == OPX_SHAPE_CYLINDER || b->kind == OPX_SHAPE_CYLINDER;
    const double tol = curved ? kCurvedTolerance : kExactTolerance;
    const Vec3 on_a(r.point_on_link[0], r.point_on_link[1], r.point_on_link[2]);
    const Vec3 on_b(r.point_on_cell[0], r.point_on_cell[1], r.point_on_cell[2]);
    if (std::abs((on_a - on_b).norm() - r.distance) > tol + 1e-12 * r.distance)
        mismatch(c.label + ": witnesses " + number((on_a - on_b).norm()) + " apart, distance " + number(r.distance));
    const Bracket pair = shape_pair_bracket(*a, *b);
    if (r.distance < pair.low - tol || r.distance > pair.high + tol)
        mismatch(c.label + ": the reported pair is " + number(pair.low) + " apart, not " + number(r.distance));
    if (has_flat_triangle(*a) || has_flat_triangle(*b)) return;
    const double da = point_core_distance(on_a, *a), db = point_core_distance(on_b, *b);
    const bool apart = r.distance > kExactTolerance;
    if ((apart && std::abs(da - a->inflation) > tol) || (!apart && da > a->inflation + tol))
        mismatch(c.label + ": point_on_link is " + number(da) + " from its core, inflation " + number(a->inflation) +
                 " (" + kind_name(a->kind) + " against the object's " + kind_name(b->kind) + ", distance " +
                 number(r.distance) + ")");
    if ((apart && std::abs(db - b->inflation) > tol) || (!apart && db > b->inflation + tol))
        mismatch(c.label + ": point_on_cell is " + number(db) + " from the object's core, inflation " +
                 number(b->inflation));
}

// ---- beside an octree --------------------------------------------------

// All contacts: the octree's (as asked without the world; a set, since an
// amortized context's order follows its tree) then the objects' (as asked
// without the octree, in their order).
void WorldChecker::check_union(opx_query *with_world, opx_query *plain, const opx_octree *tree,
                               const opx_linkset *links, const WorldCase &c, Answer &out) {
    out = collide(with_world, tree, links, c, UINT32_MAX);
    const Answer cells = collide(plain, tree, links, c, UINT32_MAX);
    const Answer objects = collide(with_world, nullptr, links, c, UINT32_MAX);
    const size_t n = cells.contacts.size();
    if (out.result.collided != (cells.result.collided || objects.result.collided) ||
        out.contacts.size() != n + objects.contacts.size())
        return mismatch(c.label + ": collision with the map and objects is not the union of the two");
    using CellContact = std::tuple<uint32_t, uint32_t, double, double, double, int32_t>;
    auto cell_of = [](const opx_contact &k) {
        return CellContact{k.link, k.shape, k.cell_center[0], k.cell_center[1], k.cell_center[2], k.object};
    };
    std::vector<CellContact> got, want;
    for (size_t i = 0; i < n; ++i) got.push_back(cell_of(out.contacts[i])), want.push_back(cell_of(cells.contacts[i]));
    std::sort(got.begin(), got.end()), std::sort(want.begin(), want.end());
    if (got != want) return mismatch(c.label + ": the map's contacts differ with the world set");
    for (size_t i = 0; i < objects.contacts.size(); ++i) {
        const opx_contact &a = out.contacts[n + i], &b = objects.contacts[i];
        if (a.link != b.link || a.shape != b.shape || a.object != b.object || a.object_shape != b.object_shape)
            return mismatch(c.label + ": object contact " + std::to_string(i) + " differs from the objects' alone");
    }
}

void WorldChecker::check_minimum(opx_query *with_world, opx_query *plain, const opx_octree *tree,
                                 const opx_linkset *links, const WorldCase &c, int32_t signed_distance, double &out) {
    bool ok_all = false, ok_cells = false, ok_objects = false;
    const opx_distance_result all = ask(with_world, tree, links, 0.0, signed_distance, 1, ok_all);
    const std::vector<double> all_links = link_distances(with_world);
    const opx_distance_result cells = ask(plain, tree, links, 0.0, signed_distance, 1, ok_cells);
    const std::vector<double> cell_links = link_distances(plain);
    const opx_distance_result objects = ask(with_world, nullptr, links, 0.0, signed_distance, 1, ok_objects);
    const std::vector<double> object_links = link_distances(with_world);
    if (!ok_all || !ok_cells || !ok_objects) return mismatch(c.label + ": opx_query_distance failed");
    const bool object_nearer = value_of(objects) < value_of(cells);
    map_object_nearest_ += object_nearer && !signed_distance;
    out = value_of(all);
    if (value_of(all) != std::min(value_of(cells), value_of(objects)) ||
        all.object != (object_nearer ? objects.object : -1))
        mismatch(c.label + ": distance " + number(value_of(all)) + " (object " + std::to_string(all.object) +
                 ") is not the least of the map's " + number(value_of(cells)) + " and the objects' " +
                 number(value_of(objects)) + (signed_distance ? " (signed)" : ""));
    for (size_t l = 0; l < all_links.size() && all_links.size() == cell_links.size(); ++l)
        if (all_links[l] != std::min(cell_links[l], l < object_links.size() ? object_links[l] : kInfinity))
            return mismatch(c.label + ": link " + std::to_string(l) + " distance is not the least of the parts'");
}

// Both engines: the union and the minimum, and the same answers.
void WorldChecker::check_with_map(opx_query *const with_world[2], opx_query *const plain[2], const opx_octree *tree,
                                  const opx_linkset *links, const WorldCase &c) {
    ++map_states_;
    Answer collision[2];
    double distance[2][2] = {{0, 0}, {0, 0}};
    for (int e = 0; e < 2; ++e) {
        check_union(with_world[e], plain[e], tree, links, c, collision[e]);
        for (int32_t s = 0; s < 2; ++s) check_minimum(with_world[e], plain[e], tree, links, c, s, distance[e][s]);
    }
    if (collision[0].result.collided != collision[1].result.collided ||
        collision[0].result.contact_count != collision[1].result.contact_count)
        mismatch(c.label + ": the direct and amortized engines collide differently");
    for (int s = 0; s < 2; ++s)
        if (!(std::abs(distance[0][s] - distance[1][s]) <= 1e-12) && distance[0][s] != distance[1][s])
            mismatch(c.label + ": the engines' distances differ: " + number(distance[0][s]) + " and " +
                     number(distance[1][s]));
}

}  // namespace oracle
