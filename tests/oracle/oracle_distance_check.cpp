#include "oracle_distance_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace oracle {
namespace {

constexpr uint64_t kPrintedMismatches = 8;

double cutoff_of(const DistanceVariant &v) { return v.cutoff > 0.0 ? v.cutoff : kNoDistance; }

// The answer may exceed the minimum by max(abs_err, rel_err * answer).
double slack_of(const DistanceVariant &v, double answer) {
    return std::max(v.abs_err, v.rel_err * (std::isfinite(answer) ? answer : 0.0));
}

const PlacedShape *find_placed(const std::vector<PlacedShape> &placed, uint32_t link, uint32_t shape) {
    for (const PlacedShape &s : placed)
        if (s.link == link && s.shape == shape) return &s;
    return nullptr;
}

// Expected `found` for a minimum m: 1 below the cutoff, 0 above, -1 when
// within the tolerance of it (either is right).
int expected_found(double m, double cutoff, double tolerance) {
    if (!std::isfinite(m) || m > cutoff + tolerance) return 0;
    if (m < cutoff - tolerance) return 1;
    return -1;
}

std::string vec(const double v[3]) {
    std::ostringstream out;
    out.precision(17);
    out << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")";
    return out.str();
}

std::string describe_nearest(const Nearest &n) {
    std::ostringstream out;
    out.precision(17);
    if (!n.shape) return "none";
    out << n.distance << " (core " << n.core << ", inflation " << n.shape->inflation << ") link " << n.shape->link
        << " shape " << n.shape->shape << " (" << kind_name(n.shape->kind) << ") cell centre ("
        << n.cell->cell.center.x() << ", " << n.cell->cell.center.y() << ", " << n.cell->cell.center.z()
        << ") size " << n.cell->size << " class " << n.cell->cell_class << (n.doubt ? " [cylinder arbitrated]" : "");
    return out.str();
}

}  // namespace

double tolerance_near(const NearestAnswer &answer, double value, int link) {
    double tolerance = kExactTolerance;
    for (const Nearest &n : answer.per_shape) {
        if (!n.shape || n.shape->kind != OPX_SHAPE_CYLINDER || (link >= 0 && int(n.shape->link) != link)) continue;
        if (n.distance <= value + kCurvedAmbiguity) tolerance = std::max(tolerance, kCurvedTolerance);
        if (n.doubt && n.distance <= value + kCurvedAmbiguity) tolerance = kCurvedAmbiguity;
    }
    return tolerance;
}

std::string describe_robot(const RobotSpec &robot) {
    std::ostringstream out;
    out.precision(17);
    out << "robot: global padding " << robot.global_padding;
    for (size_t i = 0; i < robot.links.size(); ++i) {
        const LinkSpec &link = robot.links[i];
        out << "\n      link " << i << (link.enabled ? "" : " DISABLED") << " padding " << link.padding << " pose "
            << describe_pose(link.pose);
        for (size_t j = 0; j < link.shapes.size(); ++j)
            out << "\n        shape " << j << ": " << describe_shape(link.shapes[j]);
    }
    return out.str();
}

bool DistanceChecker::check(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                            const DistanceCase &c, const DistanceVariant &v) {
    ++queries_;
    failed_ = false;
    opx_distance_request request = OPX_DISTANCE_REQUEST_INIT;
    request.unknown_policy = c.unknown_policy;
    request.occupancy_threshold = c.threshold;
    request.abs_err = v.abs_err, request.rel_err = v.rel_err;
    request.cutoff = v.cutoff;
    request.per_link = v.per_link ? 1 : 0;
    opx_distance_result r = OPX_DISTANCE_RESULT_INIT;
    const opx_status status = opx_query_distance(query, tree, links, &request, &r);
    if (status != OPX_OK) {
        mismatch(c, v, nullptr, std::string("opx_query_distance failed: ") + opx_status_name(status) + " " +
                                    opx_last_error());
        return false;
    }
    approximate_ += v.abs_err > 0.0 || v.rel_err > 0.0;
    doubtful_ += c.oracle->overall.doubt;
    check_found(c, v, r);
    if (r.found) check_pair(c, v, r);
    if (v.per_link) check_per_link(query, c, v, r);
    return !failed_;
}

void DistanceChecker::check_found(const DistanceCase &c, const DistanceVariant &v, const opx_distance_result &r) {
    const double m = c.oracle->overall.distance, cutoff = cutoff_of(v);
    const double tolerance = tolerance_near(*c.oracle, m);
    const int expected = expected_found(m, cutoff, tolerance);
    ambiguous_cutoff_ += expected < 0;
    beyond_cutoff_ += expected == 0 && std::isfinite(m);
    if (expected >= 0 && r.found != expected)
        return mismatch(c, v, &r, "found=" + std::to_string(r.found) + ", expected " + std::to_string(expected));
    if (!r.found) {
        if (r.distance != cutoff || r.collided)
            mismatch(c, v, &r, "found=0 needs distance = the cutoff (or +inf) and collided=0");
        return;
    }
    ++found_;
    collided_ += r.collided;
    const double slack = slack_of(v, r.distance);
    const double error = r.distance - m;
    if (error < -tolerance || error > slack + tolerance || !(r.distance < cutoff + tolerance))
        mismatch(c, v, &r, "distance outside [minimum, minimum + allowed error]");
    if (slack == 0.0) record_error(std::abs(error), tolerance > kExactTolerance);
    // query.h: collided follows the collision queries' touch rule (<= 1e-9 m).
    if (bool(r.collided) != (r.distance <= 1e-9)) mismatch(c, v, &r, "collided disagrees with the distance");
    const Nearest &n = c.oracle->overall;
    if (slack == 0.0 && n.shape && n.core < n.shape->inflation - tolerance && !r.collided)
        mismatch(c, v, &r, "the oracle's padded shape overlaps the cell, but collided=0");
}

void DistanceChecker::check_pair(const DistanceCase &c, const DistanceVariant &v, const opx_distance_result &r) {
    const PlacedShape *shape = find_placed(*c.placed, r.link, r.shape);
    if (!shape) return mismatch(c, v, &r, "reported link/shape is not an enabled shape of the robot");
    const CellKey key = key_of(r.cell_center, r.cell_size, c.resolution);
    const MapCell *cell = c.cells->find(key);
    if (!cell) return mismatch(c, v, &r, "reported cell is not a cell of the oracle's map");
    if (!(*c.rule)(*cell)) mismatch(c, v, &r, "reported cell is not an obstacle for the oracle");
    const Vec3 center(r.cell_center[0], r.cell_center[1], r.cell_center[2]);
    if (r.cell_size != cell->size || (center - cell->cell.center).cwiseAbs().maxCoeff() > 1e-9 * cell->size ||
        r.cell_class != cell->cell_class || r.cell_probability != cell->probability)
        mismatch(c, v, &r, "cell fields (size, centre, class, probability) differ from the oracle's cell");
    unknown_cells_ += cell->unknown();
    const PairDistance pair = pair_distance(*shape, cell->cell);
    const double tolerance = shape->kind != OPX_SHAPE_CYLINDER ? kExactTolerance
                             : pair.doubt                     ? kCurvedAmbiguity
                                                              : kCurvedTolerance;
    if (std::abs(pair.padded - r.distance) > tolerance)
        mismatch(c, v, &r, "the reported pair's exact distance is " + std::to_string(pair.padded));
    const Nearest &n = c.oracle->overall;
    ties_ += n.shape && (n.shape != shape || n.cell != cell);
    check_witness(c, v, *shape, *cell, r, tolerance);
}

void DistanceChecker::check_witness(const DistanceCase &c, const DistanceVariant &v, const PlacedShape &shape,
                                    const MapCell &cell, const opx_distance_result &r, double tolerance) {
    const Vec3 on_link(r.point_on_link[0], r.point_on_link[1], r.point_on_link[2]);
    const Vec3 on_cell(r.point_on_cell[0], r.point_on_cell[1], r.point_on_cell[2]);
    if (std::abs((on_link - on_cell).norm() - r.distance) > tolerance)
        mismatch(c, v, &r, "|point_on_link - point_on_cell| differs from the distance");
    if (point_cell_distance(on_cell, cell.cell) > kExactTolerance)
        mismatch(c, v, &r, "point_on_cell is not on the reported cell");
    if (r.distance > tolerance && std::abs(point_core_distance(shape, on_link) - shape.inflation) > tolerance)
        mismatch(c, v, &r, "point_on_link is not on the padded shape's surface (core distance " +
                                  std::to_string(point_core_distance(shape, on_link)) + ", inflation " +
                                  std::to_string(shape.inflation) + ")");
}

void DistanceChecker::check_per_link(opx_query *query, const DistanceCase &c, const DistanceVariant &v,
                                     const opx_distance_result &r) {
    ++per_link_;
    const size_t links = c.robot->links.size();
    std::vector<double> values(links + 1, -1.0);
    size_t count = 0;
    if (opx_query_get_link_distances(query, values.data(), values.size(), &count) != OPX_OK || count != links)
        return mismatch(c, v, &r, "opx_query_get_link_distances failed or gave " + std::to_string(count) + " values");
    const double cutoff = cutoff_of(v);
    double smallest = kNoDistance;
    for (size_t l = 0; l < links; ++l) {
        const double L = c.oracle->per_link[l].distance, value = values[l];
        smallest = std::min(smallest, value);
        const double tolerance = tolerance_near(*c.oracle, L, int(l));
        const int expected = c.robot->links[l].enabled ? expected_found(L, cutoff, tolerance) : 0;
        const bool within = value >= L - tolerance && value <= L + slack_of(v, value) + tolerance;
        const bool ok = expected == 0 ? value == kNoDistance
                        : expected == 1 ? within
                                        : value == kNoDistance || within;
        if (!ok)
            mismatch(c, v, &r, "link " + std::to_string(l) + ": library per-link distance " + std::to_string(value) +
                                   ", oracle " + describe_nearest(c.oracle->per_link[l]));
    }
    const bool exact = v.abs_err == 0.0 && v.rel_err == 0.0;
    if (exact && smallest != (r.found ? r.distance : kNoDistance))
        mismatch(c, v, &r, "the smallest per-link distance is not the overall one");
}

void DistanceChecker::record_error(double error, bool curved) {
    double &worst = curved ? max_curved_error_ : max_exact_error_;
    worst = std::max(worst, error);
}

void DistanceChecker::mismatch(const DistanceCase &c, const DistanceVariant &v, const opx_distance_result *r,
                               const std::string &what) {
    failed_ = true;
    if (++mismatches_ > kPrintedMismatches) return;
    std::ostringstream out;
    out.precision(17);
    out << "MISMATCH [" << name_ << "] " << c.label << ": " << what << "\n    request: unknown_policy "
        << c.unknown_policy << " threshold " << c.threshold << " abs_err " << v.abs_err << " rel_err " << v.rel_err
        << " cutoff " << v.cutoff << " per_link " << v.per_link;
    if (r)
        out << "\n    library: found " << r->found << " collided " << r->collided << " distance " << r->distance
            << " link " << r->link << " shape " << r->shape << " cell centre " << vec(r->cell_center) << " size "
            << r->cell_size << " class " << r->cell_class << " p " << r->cell_probability << "\n      point_on_link "
            << vec(r->point_on_link) << " point_on_cell " << vec(r->point_on_cell);
    out << "\n    oracle: " << describe_nearest(c.oracle->overall) << "\n    " << describe_robot(*c.robot);
    std::printf("%s\n", out.str().c_str());
}

void DistanceChecker::fail(const std::string &message) {
    failed_ = true;
    if (++mismatches_ <= kPrintedMismatches) std::printf("MISMATCH [%s] %s\n", name_.c_str(), message.c_str());
}

int DistanceChecker::finish(double seconds) const {
    const CurvedStats curved = curved_stats();
    std::printf("cylinder-cell pairs measured %llu, FCL solvers disagreed on %llu (prism brackets decided)\n",
                (unsigned long long)curved.measured, (unsigned long long)curved.disagreements);
    std::printf("SUMMARY %s: queries %llu (found %llu, collided %llu, beyond the cutoff %llu, at the cutoff %llu, "
                "approximate %llu, per-link %llu, unknown cells %llu, other pair of equal distance %llu, "
                "arbitrated cylinders %llu), mismatches %llu, max error exact kinds %.3g m, cylinders %.3g m; "
                "%.1f s\n",
                name_.c_str(), (unsigned long long)queries_, (unsigned long long)found_,
                (unsigned long long)collided_, (unsigned long long)beyond_cutoff_,
                (unsigned long long)ambiguous_cutoff_, (unsigned long long)approximate_,
                (unsigned long long)per_link_, (unsigned long long)unknown_cells_, (unsigned long long)ties_,
                (unsigned long long)doubtful_, (unsigned long long)mismatches_, max_exact_error_,
                max_curved_error_, seconds);
    return mismatches_ == 0 ? 0 : 1;
}

}  // namespace oracle
