#include "penetration_check.hpp"

#include "oracle_depth.hpp"
#include "oracle_min_distance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr uint64_t kPrintedPerKind = 3;
constexpr double kDepthTolerance = 1e-9;
constexpr double kExactMargin = 1e-7;    // the separation test's step beyond / short of the depth
constexpr double kCurvedMargin = 1e-4;   // the same for cylinders
constexpr double kUnitTolerance = 1e-9;  // (the largest deviation seen is reported)

constexpr int kFinePrism = 256;  // sides of the prisms confirming a cylinder mismatch

bool within(double depth, const DepthAnswer &o) {
    return depth >= o.low - kDepthTolerance && depth <= o.high + kDepthTolerance;
}

const PlacedShape *find_placed(const DepthCase &c, uint32_t link, uint32_t shape) {
    for (const PlacedShape &s : *c.placed)
        if (s.link == link && s.shape == shape) return &s;
    return nullptr;
}

std::string describe(const DepthCase &c, const PlacedShape *shape, const MapCell *cell) {
    std::ostringstream out;
    out.precision(17);
    out << c.label << " [" << c.scene->label << "] threshold " << c.threshold << " unknown_policy "
        << c.unknown_policy;
    if (shape) {
        const LinkSpec &link = c.robot->links[shape->link];
        out << "\n    link " << shape->link << " pose " << describe_pose(link.pose) << " padding " << link.padding
            << " + global " << c.robot->global_padding << "\n    shape " << shape->shape << ": "
            << describe_shape(link.shapes[shape->shape]) << " (inflation " << shape->inflation << ")";
    }
    if (cell)
        out << "\n    cell centre (" << cell->cell.center.transpose() << ") size " << cell->size << " p "
            << cell->probability << (cell->unknown() ? " unknown" : "");
    return out.str();
}

// The padded shape's distance to the cell, < 0 inside (cylinders: -1 or 0
// when deep).
double padded_gap(const PlacedShape &shape, const Cell &cell) { return core_cell_distance(shape, cell) - shape.inflation; }

// On the cell's surface: as far from the centre as the half edge on the
// farthest axis.
bool on_cell_surface(const Vec3 &p, const Cell &cell) {
    return std::abs((p - cell.center).cwiseAbs().maxCoeff() - cell.half) <= kDepthTolerance;
}

bool on_padded_surface(const PlacedShape &shape, const Vec3 &p) {
    const double error = core_point_distance(shape, p) - shape.inflation;
    if (shape.kind == OPX_SHAPE_MESH) return error <= kDepthTolerance;  // some triangle is nearer or as near
    return std::abs(error) <= (shape.kind == OPX_SHAPE_CYLINDER ? kCurvedMargin : kDepthTolerance);
}

void count_contact(const PlacedShape &shape, const DepthAnswer &o, const MapCell &cell, DepthReport &report) {
    ++report.contacts;
    ++report.by_kind[shape.kind];
    report.cylinder_contacts += shape.kind == OPX_SHAPE_CYLINDER ? 1 : 0;
    report.mesh_contacts += shape.kind == OPX_SHAPE_MESH ? 1 : 0;
    if (!o.exact) return;
    ++report.exact_depths;
    report.core_overlaps += o.core_overlaps ? 1 : 0;
    report.ball_only += o.core_overlaps ? 0 : 1;
    const Cell &c = cell.cell;
    report.sphere_centre_inside +=
        shape.kind == OPX_SHAPE_SPHERE && ((shape.point - c.center).cwiseAbs().array() < c.half).all() ? 1 : 0;
}

// Moving by -(depth + margin) * normal separates, by -(depth - margin) * normal does not.
std::string separation_error(const PlacedShape &shape, const Cell &cell, double depth, const Vec3 &normal,
                             DepthReport &report) {
    const double margin = shape.kind == OPX_SHAPE_CYLINDER ? kCurvedMargin : kExactMargin;
    const double out = padded_gap(translated(shape, -(depth + margin) * normal), cell);
    const double in = padded_gap(translated(shape, -(depth - margin) * normal), cell);
    const bool separated = out > 0.0, still_in = in <= 0.0;
    if (shape.kind == OPX_SHAPE_MESH && shape.triangles.size() > 1 && !separated && still_in) {
        ++report.mesh_not_separated;  // another triangle still touches: a surface has no single depth
        return "";
    }
    if (separated && still_in) return "";
    std::ostringstream text;
    text.precision(17);
    text << "moved by -(depth + " << margin << ") * normal the padded gap is " << out << " (must be > 0); by -(depth - "
         << margin << ") * normal it is " << in << " (must be <= 0)";
    return text.str();
}

void check_contact(const DepthCase &c, const opx_contact &contact, DepthReport &report) {
    const PlacedShape *shape = find_placed(c, contact.link, contact.shape);
    const MapCell *cell = c.scene->cells->find(key_of(contact.cell_center, contact.cell_size, c.scene->options.resolution));
    if (!shape || !cell) return report.mismatch(describe(c, shape, cell) + "\n    a contact with no such shape or cell");
    const DepthAnswer o = padded_depth(*shape, cell->cell);
    count_contact(*shape, o, *cell, report);
    const Vec3 normal(contact.normal), position(contact.position);
    std::ostringstream errors;
    errors.precision(17);
    report.worst_unit_error = std::max(report.worst_unit_error, std::abs(normal.norm() - 1.0));
    if (std::abs(normal.norm() - 1.0) > kUnitTolerance) errors << "\n    |normal| = " << normal.norm();
    if (o.exact && std::abs(contact.depth - o.depth) > kDepthTolerance)
        errors << "\n    depth " << contact.depth << ", oracle " << o.depth << " (core "
               << (o.core_overlaps ? "overlaps" : "apart") << ", oracle normal " << o.normal.transpose() << ")";
    if (!o.exact && !within(contact.depth, o)) {  // confirm with a tighter bracket
        const DepthAnswer fine = padded_depth(*shape, cell->cell, kFinePrism);
        if (!within(contact.depth, fine))
            errors << "\n    depth " << contact.depth << ", oracle: between " << fine.low << " and " << fine.high
                   << " (inscribed and circumscribed prisms of " << kFinePrism << " sides)";
    }
    const std::string separation = separation_error(*shape, cell->cell, contact.depth, normal, report);
    if (!separation.empty()) errors << "\n    " << separation;
    const Vec3 deepest = position + 0.5 * contact.depth * normal, exit = position - 0.5 * contact.depth * normal;
    if (!on_cell_surface(exit, cell->cell) || !on_padded_surface(*shape, deepest))
        errors << "\n    position " << position.transpose() << ": its deepest point " << deepest.transpose()
               << " is " << core_point_distance(*shape, deepest) - shape->inflation
               << " off the padded surface, its exit point " << exit.transpose() << " "
               << (exit - cell->cell.center).cwiseAbs().maxCoeff() - cell->cell.half << " off the cell's surface";
    if (errors.str().empty()) return;
    ++report.contact_mismatches[shape->kind];
    report.mismatch(describe(c, shape, cell) + "\n    contact depth " + std::to_string(contact.depth) + " normal (" +
                    std::to_string(normal.x()) + ", " + std::to_string(normal.y()) + ", " +
                    std::to_string(normal.z()) + ")" + errors.str(),
                    shape->kind);
}

void check_contacts(opx_query *query, const opx_linkset *links, const DepthCase &c, DepthReport &report) {
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.unknown_policy = c.unknown_policy;
    request.occupancy_threshold = c.threshold;
    request.max_contacts = UINT32_MAX;
    request.compute_penetration = 1;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    if (opx_query_collide(query, c.scene->tree, links, &request, &result) != OPX_OK)
        return report.mismatch(c.label + ": opx_query_collide failed: " + opx_last_error());
    for (uint64_t i = 0; i < result.contact_count; ++i) {
        opx_contact contact = OPX_CONTACT_INIT;
        if (opx_query_get_contact(query, i, &contact) != OPX_OK)
            return report.mismatch(c.label + ": opx_query_get_contact failed: " + opx_last_error());
        check_contact(c, contact, report);
    }
}

// The signed answer the oracle expects: minus the deepest depth over the
// touching pairs, bracketed when a cylinder touches (low..high).
struct SignedExpectation {
    bool touching = false, undecided = false, bracketed = false;
    double distance = kInfinity;  // the exact answer, or the middle of the bracket
    double low = kInfinity, high = kInfinity;
    double tolerance = kDepthTolerance;
};

SignedExpectation expected_signed(const DepthCase &c) {
    const ObstacleRule rule(effective_threshold(c.threshold, c.scene->options), c.unknown_policy);
    const OracleAnswer answer = oracle_collide(*c.placed, *c.scene->cells, rule);
    SignedExpectation e;
    if (answer.touching.empty() && !answer.ambiguous.empty()) e.undecided = true;
    if (!answer.touching.empty()) {
        e.touching = true;
        double deepest_low = 0.0, deepest_high = 0.0;
        for (const auto &entry : answer.touching) {
            const DepthAnswer d = padded_depth(*entry.second.shape, entry.second.cell->cell);
            e.bracketed |= !d.exact;
            deepest_low = std::max(deepest_low, d.low), deepest_high = std::max(deepest_high, d.high);
        }
        e.low = -deepest_high, e.high = -deepest_low;
        e.distance = 0.5 * (e.low + e.high);
        return e;
    }
    const ExactMinimum m = exact_min_distance(*c.placed, obstacle_list(*c.scene->cells, rule));
    e.distance = e.low = e.high = m.distance, e.tolerance = m.tolerance;
    return e;
}

std::string signed_error(const DepthCase &c, const SignedExpectation &e, const opx_distance_result &r) {
    std::ostringstream out;
    out.precision(17);
    if (e.distance == kInfinity) {
        if (r.found) out << "found = 1 with no obstacle";
        return out.str();
    }
    const bool value_ok = r.distance >= e.low - e.tolerance && r.distance <= e.high + e.tolerance;
    if (!r.found || !value_ok || r.collided != (r.distance <= 0.0 ? 1 : 0)) {
        out << "distance " << r.distance << " found " << r.found << " collided " << r.collided << ", oracle ";
        if (e.bracketed) out << "between " << e.low << " and " << e.high << " (a cylinder touches: prism brackets)";
        else out << e.distance;
    }
    const double gap = (Vec3(r.point_on_link) - Vec3(r.point_on_cell)).norm();
    const PlacedShape *shape = find_placed(c, r.link, r.shape);
    const double witness_tolerance = shape && shape->kind == OPX_SHAPE_CYLINDER ? kCurvedDistanceTolerance : kDepthTolerance;
    if (r.found && std::abs(gap - std::abs(r.distance)) > witness_tolerance)
        out << "; witnesses " << gap << " apart, |distance| " << std::abs(r.distance);
    const MapCell *cell = c.scene->cells->find(key_of(r.cell_center, r.cell_size, c.scene->options.resolution));
    if (r.found && r.distance < 0.0 && shape && cell) {
        const DepthAnswer d = padded_depth(*shape, cell->cell);
        if (!within(-r.distance, d))
            out << "; the reported pair (link " << r.link << " shape " << r.shape << ") has oracle depth " << d.low
                << (d.exact ? "" : " .. " + std::to_string(d.high));
        if (!on_cell_surface(Vec3(r.point_on_cell), cell->cell) || !on_padded_surface(*shape, Vec3(r.point_on_link)))
            out << "; a witness is off its surface";
    }
    return out.str();
}

void check_signed(opx_query *query, const opx_linkset *links, const DepthCase &c, DepthReport &report) {
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.unknown_policy = c.unknown_policy;
    request.occupancy_threshold = c.threshold;
    request.signed_distance = 1;
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    if (opx_query_distance(query, c.scene->tree, links, &request, &result) != OPX_OK)
        return report.mismatch(c.label + ": opx_query_distance failed: " + opx_last_error());
    const SignedExpectation e = expected_signed(c);
    if (e.undecided) return void(++report.signed_undecided);
    ++report.signed_checks;
    report.signed_penetrating += e.touching ? 1 : 0;
    report.signed_with_cylinder += e.bracketed ? 1 : 0;
    const std::string error = signed_error(c, e, result);
    if (error.empty()) return;
    const PlacedShape *shape = find_placed(c, result.link, result.shape);
    const MapCell *cell = c.scene->cells->find(key_of(result.cell_center, result.cell_size, c.scene->options.resolution));
    ++report.signed_mismatches[shape ? shape->kind : 0];
    report.mismatch(describe(c, shape, cell) + "\n    signed distance: " + error, shape ? shape->kind : 0);
}

}  // namespace

void DepthReport::mismatch(const std::string &message, int32_t kind) {
    ++mismatches;
    if (kind >= 0 && kind <= 6 && ++printed_[kind] <= kPrintedPerKind) std::printf("MISMATCH [%s] %s\n", name_.c_str(), message.c_str());
}

int DepthReport::finish(double seconds) const {
    std::printf("contacts by kind:");
    for (int kind = 1; kind <= 6; ++kind) std::printf(" %s %llu", kind_name(kind), (unsigned long long)by_kind[kind]);
    std::printf("\nmismatching contacts by kind:");
    for (int kind = 1; kind <= 6; ++kind)
        std::printf(" %s %llu", kind_name(kind), (unsigned long long)contact_mismatches[kind]);
    std::printf("\nmismatching signed distances by the reported shape's kind:");
    for (int kind = 0; kind <= 6; ++kind)
        std::printf(" %s %llu", kind_name(kind), (unsigned long long)signed_mismatches[kind]);
    std::printf("\nlargest | |normal| - 1 |: %.3g", worst_unit_error);
    std::printf("\nmesh contacts %llu, of which moving by the deepest triangle's depth leaves another triangle "
                "touching: %llu\n", (unsigned long long)mesh_contacts, (unsigned long long)mesh_not_separated);
    std::printf("SUMMARY %s: configurations %llu, contacts %llu (exact depths %llu: core overlapping %llu, ball "
                "only %llu, sphere centre inside %llu; cylinders %llu, depth bracketed by prisms), signed distances "
                "%llu (penetrating %llu, with a cylinder touching %llu, undecided %llu), mismatches %llu; %.1f s\n",
                name_.c_str(), (unsigned long long)configurations, (unsigned long long)contacts,
                (unsigned long long)exact_depths, (unsigned long long)core_overlaps, (unsigned long long)ball_only,
                (unsigned long long)sphere_centre_inside, (unsigned long long)cylinder_contacts,
                (unsigned long long)signed_checks, (unsigned long long)signed_penetrating,
                (unsigned long long)signed_with_cylinder, (unsigned long long)signed_undecided,
                (unsigned long long)mismatches, seconds);
    return mismatches == 0 ? 0 : 1;
}

void check_penetration(opx_query *query, const opx_linkset *links, const DepthCase &c, DepthReport &report) {
    ++report.configurations;
    check_contacts(query, links, c, report);
    check_signed(query, links, c, report);
}

}  // namespace oracle
