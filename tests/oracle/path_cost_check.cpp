#include "path_cost_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace oracle {
namespace {

constexpr double kCostRelative = 1e-9;
constexpr double kBoxCoordinate = 1e-9;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string number(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

std::string describe_box(const opx_cost_box &b) {
    std::ostringstream out;
    out.precision(17);
    out << "box link " << b.link << " class " << b.cell_class << " [" << b.min[0] << ", " << b.min[1] << ", "
        << b.min[2] << "]-[" << b.max[0] << ", " << b.max[1] << ", " << b.max[2] << "] p " << b.probability
        << " cost " << b.cost << " cell centre (" << b.cell_center[0] << ", " << b.cell_center[1] << ", "
        << b.cell_center[2] << ") size " << b.cell_size;
    return out.str();
}

std::string describe_swept(const SweptCell &s) {
    std::ostringstream out;
    out.precision(17);
    out << "oracle box [" << s.box.lo.transpose() << "]-[" << s.box.hi.transpose() << "] p " << s.probability
        << " cost " << s.cost() << " links";
    for (uint32_t l : s.links) out << " " << l;
    return out.str();
}

bool near_relative(double a, double b) { return std::abs(a - b) <= kCostRelative * std::max(std::abs(b), 1e-300) + 1e-18; }

// A kept box: the oracle's box of its cell, its probability, class and cost.
std::string kept_box_error(const PathCase &c, const SweptCost &cost, const opx_cost_box &b) {
    const CellKey key = key_of(b.cell_center, b.cell_size, c.scene->options.resolution);
    if (cost.is_sliver(key)) return b.cost <= 1e-12 ? "" : describe_box(b) + ": a sliver of the region's boundary";
    for (const SweptCell *s : cost.certain_cells()) {
        if (!(s->cell->key == key)) continue;
        const Vec3 lo(b.min), hi(b.max);
        const bool box_ok = (lo - s->box.lo).cwiseAbs().maxCoeff() <= kBoxCoordinate &&
                            (hi - s->box.hi).cwiseAbs().maxCoeff() <= kBoxCoordinate;
        const int32_t cell_class = s->cell->unknown() ? OPX_CELL_UNKNOWN : OPX_CELL_UNCERTAIN;
        if (box_ok && std::abs(b.probability - s->probability) <= 1e-12 && near_relative(b.cost, s->cost()) &&
            b.cell_class == cell_class && s->links.count(b.link))
            return "";
        return describe_box(b) + " vs " + describe_swept(*s);
    }
    return describe_box(b) + ": no such swept cell in the oracle";
}

void compare_kept(opx_query *query, const PathCase &c, const SweptCost &cost, const opx_path_result &r,
                  PathReport &report) {
    std::vector<double> costs;
    for (const SweptCell *s : cost.certain_cells()) costs.push_back(s->cost());
    std::sort(costs.rbegin(), costs.rend());
    std::vector<CellKey> seen;
    for (uint64_t i = 0; i < r.cost_box_count; ++i) {
        opx_cost_box b = OPX_COST_BOX_INIT;
        if (opx_query_get_cost_box(query, i, &b) != OPX_OK)
            return report.mismatch(describe_path_case(c) + "\n    opx_query_get_cost_box(" + std::to_string(i) +
                                   ") failed: " + opx_last_error());
        ++report.kept_boxes;
        std::string error = kept_box_error(c, cost, b);
        if (i < costs.size() && !near_relative(b.cost, costs[i]))
            error += " cost is not the " + std::to_string(i) + "-th largest " + number(costs[i]);
        const CellKey key = key_of(b.cell_center, b.cell_size, c.scene->options.resolution);
        if (std::count(seen.begin(), seen.end(), key)) error += " (cell kept twice)";
        seen.push_back(key);
        if (!error.empty()) report.mismatch(describe_path_case(c) + "\n    kept box " + std::to_string(i) + ": " + error);
    }
}

// Why the oracle leaves a cell out: the smallest padded gap between a
// shape (any waypoint) and the cell's counted part.
std::string nearest_gap(const PathCase &c, const CellKey &key) {
    const MapCell *cell = c.scene->cells->find(key);
    AlignedBox part;
    double probability = 0.0;
    if (!cell || path_cost_rule(c).counts(*cell, part, probability) == CostRule::kNone) return " (not a cost cell for the oracle)";
    double best = kInfinity;
    std::string where;
    RobotSpec robot = *c.robot;
    for (size_t w = 0; w < c.waypoints.size(); ++w) {
        for (size_t l = 0; l < robot.links.size(); ++l) robot.links[l].pose = c.waypoints[w][l];
        for (const PlacedShape &shape : place_robot(robot)) {
            const double gap = shape_aligned_distance(shape, part) - shape.inflation;
            if (gap < best)
                best = gap, where = "waypoint " + std::to_string(w) + " link " + std::to_string(shape.link) +
                                    " shape " + std::to_string(shape.shape) + " (" + kind_name(shape.kind) + ")";
        }
    }
    return "; oracle: smallest padded gap to the counted part [" + number(part.lo.x()) + ", " + number(part.lo.y()) +
           ", " + number(part.lo.z()) + "]-[" + number(part.hi.x()) + ", " + number(part.hi.y()) + ", " +
           number(part.hi.z()) + "] is " + number(best) + " at " + where;
}

// The cells only one side has (every box of the library's answer, asked
// again with no limit on the boxes kept).
std::string cell_differences(opx_query *query, const opx_linkset *links, const PathCase &c, const SweptCost &cost) {
    PathCase all = c;
    all.request.max_cost_boxes = UINT32_MAX;
    const PoseBuffer buffer = pack_waypoints(c.waypoints, c.pose_stride, c.waypoint_stride);
    opx_path_result r = OPX_PATH_RESULT_INIT;
    opx_query_path(query, c.scene->tree, links, buffer.poses(), c.waypoints.size(), c.pose_stride,
                   c.waypoint_stride, &all.request, &r);
    std::map<CellKey, opx_cost_box> library;
    for (uint64_t i = 0; i < r.cost_box_count; ++i) {
        opx_cost_box b = OPX_COST_BOX_INIT;
        opx_query_get_cost_box(query, i, &b);
        library[key_of(b.cell_center, b.cell_size, c.scene->options.resolution)] = b;
    }
    std::string out;
    int listed = 0;
    for (const SweptCell *s : cost.certain_cells())
        if (!library.erase(s->cell->key) && ++listed <= 6)  // (slivers stay in `library`)
            out += "\n    oracle only: cell centre (" + number(s->cell->cell.center.x()) + ", " +
                   number(s->cell->cell.center.y()) + ", " + number(s->cell->cell.center.z()) + ") size " +
                   number(s->cell->size) + " " + describe_swept(*s);
    for (const auto &entry : library)
        if (!cost.is_sliver(entry.first) && ++listed <= 12)
            out += "\n    library only: " + describe_box(entry.second) + nearest_gap(c, entry.first);
    return out;
}

}  // namespace

void compare_path_cost(opx_query *query, const opx_linkset *links, const PathCase &c, const SweptCost *cost,
                       const opx_path_result &r, PathReport &report) {
    if (!c.request.compute_cost) {
        if (r.total_cost != 0.0 || r.cost_boxes_found != 0 || r.cost_box_count != 0)
            report.mismatch(describe_path_case(c) + "\n    without compute_cost: total_cost " + number(r.total_cost) +
                            ", boxes " + std::to_string(r.cost_boxes_found));
        return;
    }
    if (cost->undecided()) return void(++report.undecided_costs);
    ++report.cost_checks;
    const uint64_t found = cost->certain_cells().size(), slivers = cost->touched_slivers();
    report.cost_cells += found;
    report.sliver_cells += slivers;
    const double total = cost->total_cost();
    const uint64_t kept = std::min<uint64_t>(r.cost_boxes_found, c.request.max_cost_boxes);
    if (!near_relative(r.total_cost, total) || r.cost_boxes_found < found || r.cost_boxes_found > found + slivers ||
        r.cost_box_count != kept)
        report.mismatch(describe_path_case(c) + "\n    total_cost " + number(r.total_cost) + " cells " +
                        std::to_string(r.cost_boxes_found) + " kept " + std::to_string(r.cost_box_count) +
                        "; oracle total " + number(total) + " cells " + std::to_string(found) + " (+ up to " +
                        std::to_string(slivers) + " slivers) kept min(found, " +
                        std::to_string(c.request.max_cost_boxes) + ")" + cell_differences(query, links, c, *cost));
    compare_kept(query, c, *cost, r, report);
}

}  // namespace oracle
