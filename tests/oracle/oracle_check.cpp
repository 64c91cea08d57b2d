#include "oracle_check.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <sys/stat.h>

namespace oracle {
namespace {

// Mismatches printed in full; the rest are only counted.
constexpr uint64_t kPrintedMismatches = 8;

// A cell hit by several shapes of one link appears once per shape.
std::set<std::pair<uint32_t, CellKey>> link_cell_pairs(const std::map<Triple, PairRecord> &triples) {
    std::set<std::pair<uint32_t, CellKey>> pairs;
    for (const auto &entry : triples) pairs.insert({entry.first.link, entry.first.cell});
    return pairs;
}

const PlacedShape *find_shape(const std::vector<PlacedShape> &placed, uint32_t link, uint32_t shape) {
    for (const PlacedShape &s : placed)
        if (s.link == link && s.shape == shape) return &s;
    return nullptr;
}

std::string describe_cell(const CellKey &key, double resolution) {
    const MapCell cell = cell_of_key(key, resolution);
    std::ostringstream out;
    out.precision(17);
    out << "cell center(" << cell.cell.center.x() << ", " << cell.cell.center.y() << ", "
        << cell.cell.center.z() << ") size " << cell.size << " depth " << key.depth;
    return out.str();
}

}  // namespace

namespace {

// The margin added to every bound: larger than every ambiguity band, so a
// pair the bounds skip is clear.
constexpr double kBoundsMargin = 1e-4;

// Minimum core distance of a mesh to each obstacle cell near one of its
// triangles.  A cell already certainly touched is not measured again.
void mesh_distances(const PlacedShape &mesh, const CellIndex &cells, const ObstacleRule &rule,
                    std::map<uint32_t, double> &best) {
    const double reach = mesh.inflation + kBoundsMargin;
    const double certain = mesh.inflation - kBoundsMargin;
    std::vector<uint32_t> near;
    for (const Triangle &t : mesh.triangles) {
        const Vec3 low = t.a.cwiseMin(t.b).cwiseMin(t.c) - Vec3::Constant(reach);
        const Vec3 high = t.a.cwiseMax(t.b).cwiseMax(t.c) + Vec3::Constant(reach);
        cells.candidates(low, high, near);
        for (uint32_t i : near) {
            const MapCell &cell = cells.cells()[i];
            const Vec3 cell_half = Vec3::Constant(cell.cell.half);
            if (!rule(cell) || (low - cell.cell.center - cell_half).maxCoeff() > 0.0 ||
                (cell.cell.center - cell_half - high).maxCoeff() > 0.0)
                continue;  // (the triangle's grown bounds miss the cell)
            const auto found = best.find(i);
            if (found != best.end() && found->second < certain) continue;
            const double d = triangle_cell_distance(t, cell.cell);
            if (found == best.end()) best[i] = d;
            else found->second = std::min(found->second, d);
        }
    }
}

void solid_distances(const PlacedShape &shape, const CellIndex &cells, const ObstacleRule &rule,
                     std::map<uint32_t, double> &best) {
    std::vector<uint32_t> near;
    cells.candidates(shape.bounds_min - Vec3::Constant(kBoundsMargin),
                     shape.bounds_max + Vec3::Constant(kBoundsMargin), near);
    for (uint32_t i : near) {
        const MapCell &cell = cells.cells()[i];
        if (!rule(cell) || bounds_gap(shape, cell.cell) > kBoundsMargin) continue;
        best[i] = shape_cell_distance(shape, cell.cell, shape.inflation + kBoundsMargin);
    }
}

}  // namespace

OracleAnswer oracle_collide(const std::vector<PlacedShape> &placed, const CellIndex &cells,
                            const ObstacleRule &rule) {
    OracleAnswer answer;
    for (const PlacedShape &shape : placed) {
        std::map<uint32_t, double> best;  // cell index -> core distance
        if (shape.kind == OPX_SHAPE_MESH) mesh_distances(shape, cells, rule, best);
        else solid_distances(shape, cells, rule, best);
        for (const auto &[index, distance] : best) {
            const Verdict verdict = judge(shape, distance);
            if (verdict == Verdict::kClear) continue;
            const MapCell &cell = cells.cells()[index];
            auto &bucket = verdict == Verdict::kTouch ? answer.touching : answer.ambiguous;
            bucket[{shape.link, shape.shape, cell.key}] = {&shape, &cell, distance};
        }
    }
    return answer;
}

struct Checker::LibraryAnswer {
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    std::vector<opx_contact> contacts;
};

Checker::LibraryAnswer Checker::ask(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                    const QueryCase &c, uint32_t max_contacts) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.unknown_policy = c.unknown_policy;
    request.occupancy_threshold = c.threshold;
    request.max_contacts = max_contacts;
    LibraryAnswer answer;
    const opx_status status = opx_query_collide(query, tree, links, &request, &answer.result);
    if (status != OPX_OK) {
        mismatch(c.label + ": opx_query_collide failed: " + opx_status_name(status) + " " + opx_last_error());
        return answer;
    }
    for (size_t i = 0; i < answer.result.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        if (opx_query_get_contact(query, i, &contact) != OPX_OK) {
            mismatch(c.label + ": opx_query_get_contact failed: " + opx_last_error());
            break;
        }
        answer.contacts.push_back(contact);
    }
    return answer;
}

bool Checker::check(opx_query *query, const opx_octree *tree, const opx_linkset *links, const QueryCase &c) {
    ++queries_;
    query_failed_ = false;
    const ObstacleRule rule(c.threshold > 0.0 ? c.threshold : c.occupied_threshold, c.unknown_policy);
    const OracleAnswer oracle = oracle_collide(*c.placed, *c.cells, rule);
    ambiguous_pairs_ += oracle.ambiguous.size();
    for (const auto &entry : oracle.ambiguous) ++ambiguous_by_kind_[entry.second.shape->kind];
    const bool undecided = oracle.touching.empty() && !oracle.ambiguous.empty();
    ambiguous_queries_ += undecided ? 1 : 0;
    collided_ += oracle.touching.empty() ? 0 : 1;

    const LibraryAnswer first = ask(query, tree, links, c, 1);
    compare_collided(c, oracle, first, "max_contacts=1");
    if (first.result.contact_count != (first.result.collided ? 1u : 0u))
        mismatch(c.label + ": max_contacts=1 gave " + std::to_string(first.result.contact_count) +
                 " contacts, collided=" + std::to_string(first.result.collided));
    max1_truncated_ += first.result.truncated ? 1 : 0;

    const LibraryAnswer all = ask(query, tree, links, c, UINT32_MAX);
    compare_collided(c, oracle, all, "max_contacts=UINT32_MAX");
    if (all.result.truncated) mismatch(c.label + ": max_contacts=UINT32_MAX reported truncated=1");
    compare_contacts(c, oracle, all);
    contacts_ += all.contacts.size();
    for (const opx_contact &contact : all.contacts) {
        coarse_contacts_ += contact.cell_size > 1.5 * c.resolution ? 1 : 0;  // a pruned leaf or a big cube
        unknown_contacts_ += contact.cell_class == OPX_CELL_UNKNOWN ? 1 : 0;
    }
    check_truncation(query, tree, links, c, oracle, all.contacts.size());
    return !query_failed_;
}

void Checker::compare_collided(const QueryCase &c, const OracleAnswer &oracle, const LibraryAnswer &lib,
                               const char *call) {
    if (oracle.touching.empty() && !oracle.ambiguous.empty()) return;  // undecided
    const bool expected = !oracle.touching.empty();
    if (bool(lib.result.collided) == expected) return;
    std::ostringstream out;
    out << c.label << ": " << call << " collided=" << lib.result.collided << " but the oracle says "
        << (expected ? "collision" : "no collision");
    if (expected) {
        const auto &[triple, record] = *oracle.touching.begin();
        out << "; e.g. link " << triple.link << " shape " << triple.shape << " at distance "
            << record.distance << " <= inflation " << record.shape->inflation << " from "
            << describe_cell(triple.cell, c.resolution);
        mismatch(out.str());
        report_pair(c, triple, "oracle touches", "library: no collision");
        return;
    }
    mismatch(out.str());
    for (const opx_contact &contact : lib.contacts)  // what the library hit, when it says
        report_pair(c, {contact.link, contact.shape, key_of(contact.cell_center, contact.cell_size, c.resolution)},
                    "library-only collision", "library reports this contact");
}

void Checker::compare_contacts(const QueryCase &c, const OracleAnswer &oracle, const LibraryAnswer &lib) {
    std::map<Triple, PairRecord> reported;
    for (const opx_contact &contact : lib.contacts) {
        const Triple t{contact.link, contact.shape, key_of(contact.cell_center, contact.cell_size, c.resolution)};
        if (reported.count(t)) report_pair(c, t, "DUPLICATE contact", "library reports it twice");
        reported[t] = {};
        check_contact_fields(c, contact);
        if (!oracle.touching.count(t) && !oracle.ambiguous.count(t))
            report_pair(c, t, "library-only contact", "library reports a contact");
    }
    for (const auto &entry : oracle.touching)
        if (!reported.count(entry.first)) report_pair(c, entry.first, "missed contact", "library: no contact");
    // (link, cell) pairs: implied by the triples, counted for the record.
    const auto library_pairs = link_cell_pairs(reported);
    for (const auto &pair : link_cell_pairs(oracle.touching))
        if (!library_pairs.count(pair))
            mismatch(c.label + ": (link " + std::to_string(pair.first) + ", " +
                     describe_cell(pair.second, c.resolution) + ") missing at the (link, cell) level");
}

void Checker::check_contact_fields(const QueryCase &c, const opx_contact &contact) {
    const CellKey key = key_of(contact.cell_center, contact.cell_size, c.resolution);
    const MapCell *cell = c.cells->find(key);
    std::ostringstream out;
    out.precision(17);
    out << c.label << ": contact link " << contact.link << " shape " << contact.shape << " "
        << describe_cell(key, c.resolution);
    if (!cell) return mismatch(out.str() + ": not a cell of the oracle's map");
    const bool same_center = (cell->cell.center - Vec3(contact.cell_center[0], contact.cell_center[1],
                                                       contact.cell_center[2])).cwiseAbs().maxCoeff() <=
                             1e-9 * cell->size;
    if (contact.cell_size != cell->size || !same_center || contact.cell_probability != cell->probability ||
        contact.cell_class != cell->cell_class)
        mismatch(out.str() + ": fields size " + std::to_string(contact.cell_size) + " p " +
                 std::to_string(contact.cell_probability) + " class " + std::to_string(contact.cell_class) +
                 " vs oracle size " + std::to_string(cell->size) + " p " + std::to_string(cell->probability) +
                 " class " + std::to_string(cell->cell_class) + (same_center ? "" : " (centre differs)"));
}

// max_contacts 0: the yes/no answer, no contact.  N < total: exactly N
// contacts (a subset) and truncated=1.  N == total: all, truncated=0.
void Checker::check_truncation(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                               const QueryCase &c, const OracleAnswer &oracle, uint64_t total) {
    const LibraryAnswer none = ask(query, tree, links, c, 0);
    compare_collided(c, oracle, none, "max_contacts=0");
    if (none.result.contact_count != 0) mismatch(c.label + ": max_contacts=0 returned contacts");
    max0_truncated_ += none.result.truncated ? 1 : 0;
    if (total < 2) return;
    ++truncation_checks_;
    const uint32_t limits[2] = {uint32_t(2 + (queries_ * 7919) % (total - 1)), uint32_t(total)};
    for (uint32_t limit : limits) {
        const LibraryAnswer some = ask(query, tree, links, c, limit);
        const bool want_truncated = limit < total;
        if (some.contacts.size() != limit || bool(some.result.truncated) != want_truncated || !some.result.collided)
            mismatch(c.label + ": max_contacts=" + std::to_string(limit) + " of " + std::to_string(total) +
                     " gave " + std::to_string(some.contacts.size()) + " contacts, truncated=" +
                     std::to_string(some.result.truncated));
        for (const opx_contact &contact : some.contacts) {
            const Triple t{contact.link, contact.shape, key_of(contact.cell_center, contact.cell_size, c.resolution)};
            if (!oracle.touching.count(t) && !oracle.ambiguous.count(t))
                report_pair(c, t, "library-only contact (truncated list)", "library reports a contact");
        }
    }
}

void Checker::report_pair(const QueryCase &c, const Triple &t, const char *what, const char *library_says) {
    std::ostringstream out;
    out.precision(17);
    out << c.label << ": " << what << ": " << library_says << "; request unknown_policy=" << c.unknown_policy
        << " threshold=" << c.threshold << "\n    link " << t.link;
    if (t.link < c.robot->links.size()) {
        const LinkSpec &link = c.robot->links[t.link];
        out << " '" << link.name << "' pose " << describe_pose(link.pose) << " padding " << link.padding
            << " + global " << c.robot->global_padding << (link.enabled ? "" : " DISABLED");
        if (t.shape < link.shapes.size()) out << "\n    shape " << t.shape << ": " << describe_shape(link.shapes[t.shape]);
    }
    out << "\n    " << describe_cell(t.cell, c.resolution);
    const MapCell *cell = c.cells->find(t.cell);
    const PlacedShape *shape = find_shape(*c.placed, t.link, t.shape);
    const ObstacleRule rule(c.threshold > 0.0 ? c.threshold : c.occupied_threshold, c.unknown_policy);
    if (cell) out << " p " << cell->probability << " class " << cell->cell_class
                  << (rule(*cell) ? " (obstacle)" : " (NOT an obstacle for the oracle)");
    else out << " (not a cell of the oracle's map)";
    if (cell && shape)
        out << "\n    oracle distance " << shape_cell_distance(*shape, cell->cell, 1e300) << " vs inflation "
            << shape->inflation;
    mismatch(out.str());
}

void Checker::mismatch(const std::string &message) {
    query_failed_ = true;
    if (++mismatches_ <= kPrintedMismatches) std::printf("MISMATCH [%s] %s\n", name_.c_str(), message.c_str());
}

void Checker::fail(const std::string &message) { mismatch(message); }

int Checker::finish(double seconds) const {
    const CurvedStats curved = curved_stats();
    std::printf("cylinder-cell pairs measured %llu: FCL solvers disagreed on %llu (decided by exact prism "
                "brackets), brackets wider than the band %llu\n",
                (unsigned long long)curved.measured, (unsigned long long)curved.disagreements,
                (unsigned long long)curved.unresolved);
    if (ambiguous_pairs_ > 0) {
        std::printf("ambiguous pairs by kind:");
        for (int kind = 1; kind <= 6; ++kind)
            if (ambiguous_by_kind_[kind]) std::printf(" %s %llu", kind_name(kind), (unsigned long long)ambiguous_by_kind_[kind]);
        std::printf("\n");
    }
    std::printf("contacts with cells larger than the resolution: %llu, with unknown cubes: %llu\n",
                (unsigned long long)coarse_contacts_, (unsigned long long)unknown_contacts_);
    std::printf("SUMMARY %s: queries %llu (collided %llu), contacts %llu, truncation checks %llu, "
                "mismatches %llu, ambiguous pairs %llu, undecided queries %llu, "
                "truncated=1 with max_contacts 1: %llu, with 0: %llu; %.1f s\n",
                name_.c_str(), (unsigned long long)queries_, (unsigned long long)collided_,
                (unsigned long long)contacts_, (unsigned long long)truncation_checks_,
                (unsigned long long)mismatches_, (unsigned long long)ambiguous_pairs_,
                (unsigned long long)ambiguous_queries_, (unsigned long long)max1_truncated_,
                (unsigned long long)max0_truncated_, seconds);
    return mismatches_ == 0 ? 0 : 1;
}

std::string data_path(const char *relative) {
    const char *env = std::getenv("OPX_DATA_DIR");
#ifdef OPX_DEFAULT_DATA_DIR
    const std::string root = env && *env ? env : OPX_DEFAULT_DATA_DIR;
#else
    const std::string root = env && *env ? env : "";
#endif
    const std::string path = root + "/" + relative;
    struct stat info;
    if (root.empty() || stat(path.c_str(), &info) != 0) {
        const char *required = std::getenv("OPX_REQUIRE_DATA");
        if (required != nullptr && std::string(required) == "1") {
            std::printf("FAIL: %s not found and OPX_REQUIRE_DATA=1: the shared data is required\n", path.c_str());
            std::fflush(stdout);
            std::exit(1);
        }
        std::printf("SKIP: %s not found (set OPX_DATA_DIR to the shared data folder)\n", path.c_str());
        return "";
    }
    return path;
}

uint64_t env_number(const char *name, uint64_t fallback) {
    const char *value = std::getenv(name);
    return value && *value ? std::strtoull(value, nullptr, 10) : fallback;
}

double elapsed_seconds() {
    static const auto start = std::chrono::steady_clock::now();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace oracle
