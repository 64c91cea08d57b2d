#include "oracle_path_check.hpp"

#include "oracle_min_distance.hpp"
#include "path_cost_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <sstream>

namespace oracle {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr uint64_t kPrintedMismatches = 8;

struct WaypointOracle {
    bool touching = false, ambiguous = false;
    double distance = kInfinity;  // with compute_distance
    double tolerance = kExactDistanceTolerance;
    std::string nearest;          // the pair at that distance, described
};

struct PathOracle {
    std::vector<WaypointOracle> waypoints;
    std::unique_ptr<SweptCost> cost;
};

bool explicit_region(const opx_path_request &r) {
    for (int k = 0; k < 3; ++k)
        if (!(r.region_min[k] < r.region_max[k])) return false;
    return true;
}

double threshold_of(const PathCase &c) {
    return effective_threshold(c.request.occupancy_threshold, c.scene->options);
}

}  // namespace

CostRule path_cost_rule(const PathCase &c) {
    CostRule rule;
    rule.threshold_log_odds = float_logit(threshold_of(c));
    rule.free_log_odds = float_logit(c.scene->options.free_threshold);
    rule.unknown_occupied = c.request.unknown_policy == OPX_UNKNOWN_OCCUPIED;
    rule.unknown_probability = c.request.unknown_probability;
    rule.region = explicit_region(c.request)
                      ? AlignedBox{Vec3(c.request.region_min), Vec3(c.request.region_max)}
                      : observed_bounds(c.scene->leaves);
    return rule;
}

namespace {

std::string describe_pair(const PlacedShape *shape, const MapCell *cell) {
    if (!shape || !cell) return "(none)";
    std::ostringstream out;
    out.precision(17);
    out << "link " << shape->link << " shape " << shape->shape << " (" << kind_name(shape->kind)
        << ", inflation " << shape->inflation << ") vs cell centre (" << cell->cell.center.transpose()
        << ") size " << cell->size << " p " << cell->probability;
    return out.str();
}

PathOracle run_oracle(const PathCase &c) {
    const bool distance = c.request.compute_distance != 0, cost = c.request.compute_cost != 0;
    const ObstacleRule rule(threshold_of(c), c.request.unknown_policy);
    const std::vector<const MapCell *> obstacles = distance ? obstacle_list(*c.scene->cells, rule)
                                                            : std::vector<const MapCell *>();
    PathOracle oracle;
    if (cost) oracle.cost = std::make_unique<SweptCost>(path_cost_rule(c));
    RobotSpec robot = *c.robot;
    for (const std::vector<opx_pose> &poses : c.waypoints) {
        for (size_t l = 0; l < robot.links.size(); ++l) robot.links[l].pose = poses[l];
        const std::vector<PlacedShape> placed = place_robot(robot);
        const OracleAnswer answer = oracle_collide(placed, *c.scene->cells, rule);
        WaypointOracle w;
        w.touching = !answer.touching.empty(), w.ambiguous = !answer.ambiguous.empty();
        if (distance) {
            const ExactMinimum m = exact_min_distance(placed, obstacles);
            w.distance = m.distance, w.tolerance = m.tolerance;
            w.nearest = describe_pair(m.shape, m.cell);
        }
        if (cost) oracle.cost->add_configuration(placed, *c.scene->cells);
        oracle.waypoints.push_back(w);
        if (w.touching && !distance && !cost) break;  // the library stops here too
    }
    return oracle;
}

// A mesh with vertices no triangle uses: the library's link bounding box
// takes them in (a known difference, see the final report).
bool has_unused_vertices(const ShapeSpec &s) {
    if (s.kind != OPX_SHAPE_MESH) return false;
    std::vector<bool> used(s.vertices.size(), false);
    for (const auto &t : s.triangles)
        for (uint32_t i : t) used[i] = true;
    return std::count(used.begin(), used.end(), false) > 0;
}

}  // namespace

std::string describe_path_case(const PathCase &c) {
    std::ostringstream out;
    out.precision(17);
    const opx_path_request &r = c.request;
    out << c.label << " [" << c.scene->label << "]: " << c.waypoints.size() << " waypoints, pose_stride "
        << c.pose_stride << ", waypoint_stride " << c.waypoint_stride << "; request unknown_policy "
        << r.unknown_policy << " threshold " << r.occupancy_threshold << " distance " << r.compute_distance
        << " cost " << r.compute_cost << " max_cost_boxes " << r.max_cost_boxes << " unknown_p "
        << r.unknown_probability << " region (" << r.region_min[0] << ", " << r.region_min[1] << ", "
        << r.region_min[2] << ")-(" << r.region_max[0] << ", " << r.region_max[1] << ", " << r.region_max[2]
        << ")\n    robot: global padding " << c.robot->global_padding;
    for (size_t l = 0; l < c.robot->links.size(); ++l) {
        const LinkSpec &link = c.robot->links[l];
        out << "\n    link " << l << " padding " << link.padding << (link.enabled ? "" : " DISABLED");
        for (const ShapeSpec &s : link.shapes)
            out << "\n      " << describe_shape(s)
                << (has_unused_vertices(s) ? "\n      ^ this mesh has vertices no triangle uses" : "");
    }
    return out.str();
}

namespace {

std::string describe_waypoint(const PathCase &c, int64_t w) {
    if (w < 0 || size_t(w) >= c.waypoints.size()) return "";
    std::ostringstream out;
    out << "\n    waypoint " << w << ":";
    for (size_t l = 0; l < c.waypoints[w].size(); ++l) out << "\n      link " << l << " " << describe_pose(c.waypoints[w][l]);
    return out.str();
}

std::string number(double value) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

void compare_collision(const PathCase &c, const PathOracle &o, const opx_path_result &r, PathReport &report) {
    int64_t expected = -1;
    bool undecided = false;
    for (size_t w = 0; w < o.waypoints.size() && expected < 0; ++w) {
        if (o.waypoints[w].touching) expected = int64_t(w);
        undecided |= o.waypoints[w].ambiguous && !o.waypoints[w].touching;
    }
    report.undecided_collisions += undecided ? 1 : 0;
    report.collided += expected >= 0 ? 1 : 0;
    const int64_t got = r.first_colliding_waypoint;
    const bool doubtful = got >= 0 && size_t(got) < o.waypoints.size() && o.waypoints[got].ambiguous &&
                          (expected < 0 || got < expected);
    if ((got == expected || doubtful) && r.collided == (got >= 0 ? 1 : 0)) return;
    report.mismatch(describe_path_case(c) + "\n    first_colliding_waypoint " + std::to_string(got) + " collided " +
                    std::to_string(r.collided) + ", oracle: first touching waypoint " + std::to_string(expected) +
                    describe_waypoint(c, expected) + describe_waypoint(c, got));
}

void compare_distance(const PathCase &c, const PathOracle &o, const opx_path_result &r, PathReport &report) {
    if (!c.request.compute_distance) {
        if (r.min_distance != kInfinity || r.min_distance_waypoint != -1)
            report.mismatch(describe_path_case(c) + "\n    without compute_distance: min_distance " +
                            number(r.min_distance) + " waypoint " + std::to_string(r.min_distance_waypoint));
        return;
    }
    double best = kInfinity, tolerance = kExactDistanceTolerance;
    for (const WaypointOracle &w : o.waypoints) best = std::min(best, w.distance);
    for (const WaypointOracle &w : o.waypoints)
        if (w.distance <= best + kCurvedDistanceTolerance) tolerance = std::max(tolerance, w.tolerance);
    ++report.distance_checks;
    report.positive_distances += best > 0.0 && best < kInfinity ? 1 : 0;
    report.curved_distance_checks += tolerance > kExactDistanceTolerance ? 1 : 0;
    const int64_t w = r.min_distance_waypoint;
    bool ok = best == kInfinity ? r.min_distance == kInfinity && w == -1
                                : std::abs(r.min_distance - best) <= tolerance && w >= 0 &&
                                      size_t(w) < o.waypoints.size() &&
                                      std::abs(o.waypoints[w].distance - best) <= tolerance;
    if (ok) return;
    int64_t argmin = -1;
    for (size_t i = 0; i < o.waypoints.size(); ++i)
        if (argmin < 0 && o.waypoints[i].distance == best) argmin = int64_t(i);
    report.mismatch(describe_path_case(c) + "\n    min_distance " + number(r.min_distance) + " at waypoint " +
                    std::to_string(w) + "; oracle " + number(best) + " at waypoint " + std::to_string(argmin) +
                    " (" + (argmin >= 0 ? o.waypoints[argmin].nearest : "") + "), oracle at the library's waypoint " +
                    (w >= 0 && size_t(w) < o.waypoints.size() ? number(o.waypoints[w].distance) : "-") +
                    describe_waypoint(c, argmin) + describe_waypoint(c, w));
}

}  // namespace

PoseBuffer pack_waypoints(const Waypoints &waypoints, size_t pose_stride, size_t waypoint_stride) {
    PoseBuffer buffer;
    buffer.pose_stride = pose_stride, buffer.waypoint_stride = waypoint_stride;
    const size_t links = waypoints.empty() ? 0 : waypoints.front().size();
    const size_t step = pose_stride == 0 ? sizeof(opx_pose) : pose_stride;
    const size_t row = waypoint_stride == 0 ? links * step : waypoint_stride;
    const size_t bytes = waypoints.empty() ? 0 : (waypoints.size() - 1) * row + (links - 1) * step + sizeof(opx_pose);
    buffer.storage.assign(bytes / sizeof(double) + 1, std::nan(""));
    auto *base = reinterpret_cast<unsigned char *>(buffer.storage.data());
    for (size_t w = 0; w < waypoints.size(); ++w)
        for (size_t l = 0; l < links; ++l) std::memcpy(base + w * row + l * step, &waypoints[w][l], sizeof(opx_pose));
    return buffer;
}

void PathReport::mismatch(const std::string &message) {
    if (++mismatches <= kPrintedMismatches) std::printf("MISMATCH [%s] %s\n", name_.c_str(), message.c_str());
}

int PathReport::finish(double seconds) const {
    std::printf("SUMMARY %s: paths %llu, waypoints %llu, collided %llu (stopped at the first collision %llu), "
                "distance checks %llu (positive %llu, cylinder-tolerance %llu), cost checks %llu (swept cells %llu, region-boundary "
                "slivers %llu, kept boxes %llu), paths with cost mismatches %llu (%llu with a mesh that has vertices "
                "no triangle uses), special-case checks %llu, undecided collisions %llu, undecided costs %llu, mismatches "
                "%llu; %.1f s\n",
                name_.c_str(), (unsigned long long)paths, (unsigned long long)waypoints,
                (unsigned long long)collided, (unsigned long long)stopped_early, (unsigned long long)distance_checks, (unsigned long long)positive_distances,
                (unsigned long long)curved_distance_checks, (unsigned long long)cost_checks,
                (unsigned long long)cost_cells, (unsigned long long)sliver_cells, (unsigned long long)kept_boxes,
                (unsigned long long)(cost_paths_other + cost_paths_unused_vertices),
                (unsigned long long)cost_paths_unused_vertices, (unsigned long long)special_checks,
                (unsigned long long)undecided_collisions, (unsigned long long)undecided_costs,
                (unsigned long long)mismatches, seconds);
    return mismatches == 0 ? 0 : 1;
}

bool check_path(opx_query *query, const opx_linkset *links, const PathCase &c, PathReport &report) {
    const uint64_t before = report.mismatches;
    ++report.paths;
    report.waypoints += c.waypoints.size();
    const PoseBuffer buffer = pack_waypoints(c.waypoints, c.pose_stride, c.waypoint_stride);
    opx_path_result result = OPX_PATH_RESULT_INIT;
    const opx_status status = opx_query_path(query, c.scene->tree, links, buffer.poses(), c.waypoints.size(),
                                             c.pose_stride, c.waypoint_stride, &c.request, &result);
    if (status != OPX_OK) {
        report.mismatch(describe_path_case(c) + "\n    opx_query_path failed: " + opx_status_name(status) + " " +
                        opx_last_error());
        return false;
    }
    const PathOracle oracle = run_oracle(c);
    const bool plain = !c.request.compute_distance && !c.request.compute_cost;
    report.stopped_early += plain && result.first_colliding_waypoint >= 0 ? 1 : 0;
    compare_collision(c, oracle, result, report);
    compare_distance(c, oracle, result, report);
    const uint64_t before_cost = report.mismatches;
    compare_path_cost(query, links, c, oracle.cost.get(), result, report);
    if (report.mismatches > before_cost) {
        bool unused = false;
        for (const LinkSpec &link : c.robot->links)
            for (const ShapeSpec &s : link.shapes) unused |= link.enabled && has_unused_vertices(s);
        ++(unused ? report.cost_paths_unused_vertices : report.cost_paths_other);
    }
    return report.mismatches == before;
}

}  // namespace oracle