// FCL's octree and box distance issues, reproduced with this library, with
// the true answers worked out by hand.  Each case asserts the distance
// (1e-9 m), the witness points (point_on_link on the link's box,
// point_on_cell on the reported cell, |difference| == distance) and the
// oracle's agreement.
//
// Maps: OctoMap's updateNode(p, true) is one hit on the cell holding p; here
// that is an OPX_INSERT_ENDPOINTS frame seen from the identity pose (one hit
// per endpoint cell).  Cells are cubes [k r, (k + 1) r] per axis (k =
// floor(coordinate / r)), so at r = 0.1 the point (9, 0, 0) occupies
// [9, 9.1] x [0, 0.1] x [0, 0.1].
//
// #640 "Distance calculation bug between Box and OcTree geometries persists
//   in FCL 0.7.0": OcTree(0.1) with (1,0,0), (9,0,0), (12,0,1); a 1 x 1 x 1
//   box at (10, 0, 0).  The issue reports a 9+ m discrepancy between FCL's
//   min_distance and the distance of its nearest points.
// #639 "Inconsistent DistanceResult: min_distance vs. nearest_points for
//   fcl::OcTree": the same author's setup with the drone at (10, 0, 5); the
//   issue prints an octree of 3 points at 0.1 m with 30 nodes (the #640 tree
//   has exactly 30 nodes in OctoMap 1.9.7) and a box-local witness
//   (0.5, 0, -0.5), i.e. a 1 m box.  The drone's size and the three points
//   are not in the part of the issue available to us: we use the #640 tree
//   and drone (closest faithful configuration).  The issue's FCL value,
//   3.76962 = sqrt(3.5^2 + 1.4^2), belongs to a configuration we could not
//   recover; for ours the answer is sqrt(13.81) (below).
// #504 "Reversed nearest points result when computing distance with octree":
//   OcTree(0.1) with updateNode((1, 0, 0), log-odds 1.0) and a 0.1 m box at
//   the origin; FCL returns the octree's point first.  A hit gives log-odds
//   0.85 here instead of 1.0: occupied either way, same distance.  Our
//   result names its points (point_on_link, point_on_cell): the box's point
//   must be point_on_link.
// #508 "Wrong Box to Box distance with GST_LIBCCD solver": two 1 m boxes,
//   one at the origin, one at (0, 4, 0): 3.0 expected, libccd gave 3.16228;
//   wrong for translations along y or z above 1.99, and similarly for 2 m
//   boxes.  The box at the origin is the map: the cube [-0.5, 0.5]^3 is 8
//   cells at r = 0.5 ([-1, 1]^3 for the 2 m box: 8 cells at r = 1), the
//   other box is the link; translations swept along +-x, +-y, +-z.
#include "oracle_engine.hpp"
#include "oracle_distance_check.hpp"
#include "oracle_enclosure.hpp"

#include <cmath>
#include <cstdio>

using namespace oracle;

namespace {

int failures = 0, cases = 0;
double max_error = 0.0;

void expect(bool ok, const std::string &what) {
    if (ok) return;
    ++failures;
    std::printf("MISMATCH [oracle_fcl_issues] %s\n", what.c_str());
}

RobotSpec box_robot(double edge, const Vec3 &position) {
    ShapeSpec box;
    box.kind = OPX_SHAPE_BOX;
    box.size = Vec3::Constant(edge);
    RobotSpec robot;
    robot.links.push_back({"box", {box}, 0.0, true, {{position.x(), position.y(), position.z()}, {0, 0, 0, 1}}});
    return robot;
}

Vec3 vec(const double v[3]) { return Vec3(v[0], v[1], v[2]); }

// Asks the library, checks the hand-worked distance, the witness points and
// the oracle; returns the result for case-specific witness checks.
opx_distance_result run(const std::string &name, const Scene &scene, const RobotSpec &robot, double expected,
                        opx_query *query) {
    opx_linkset *links = build_linkset(robot);
    opx_distance_result r = OPX_DISTANCE_RESULT_INIT;
    expect(opx_query_distance(query, scene.tree, links, nullptr, &r) == OPX_OK, name + ": opx_query_distance failed");
    opx_linkset_destroy(links);
    const Vec3 on_link = vec(r.point_on_link), on_cell = vec(r.point_on_cell);
    ++cases;
    max_error = std::max(max_error, std::abs(r.distance - expected));
    std::printf("%-44s expected %.12f library %.12f on_link (%.6g, %.6g, %.6g) on_cell (%.6g, %.6g, %.6g)\n",
                name.c_str(), expected, r.distance, on_link.x(), on_link.y(), on_link.z(), on_cell.x(), on_cell.y(),
                on_cell.z());
    expect(r.found == 1 && std::abs(r.distance - expected) <= kExactTolerance,
           name + ": distance " + std::to_string(r.distance) + ", hand-worked " + std::to_string(expected));
    expect(std::abs((on_link - on_cell).norm() - r.distance) <= kExactTolerance,
           name + ": the witness points are not `distance` apart");
    const std::vector<PlacedShape> placed = place_robot(robot);
    expect(std::abs(point_core_distance(placed[0], on_link)) <= kExactTolerance,
           name + ": point_on_link is not on the link's box");
    const Cell cell{vec(r.cell_center), 0.5 * r.cell_size};
    expect(point_cell_distance(on_cell, cell) <= kExactTolerance, name + ": point_on_cell is not on the cell");
    const ObstacleRule rule(scene.options.occupied_threshold, OPX_UNKNOWN_FREE);
    const NearestAnswer oracle = oracle_nearest(placed, 1, obstacle_cells(*scene.cells, rule));
    expect(std::abs(oracle.overall.distance - expected) <= kExactTolerance, name + ": the oracle disagrees");
    return r;
}

std::unique_ptr<Scene> drone_tree() {  // #639 and #640
    std::unique_ptr<Scene> scene = cells_scene(0.1, {Vec3(1, 0, 0), Vec3(9, 0, 0), Vec3(12, 0, 1)}, false);
    expect(scene->leaves.size() == 3, "the #640 tree has 3 occupied cells");
    return scene;
}

void issue_640(opx_query *query) {
    // Box [9.5, 10.5] x [-0.5, 0.5]^2.  Cells: [9, 9.1] x [0, 0.1]^2 is 0.4
    // away along x (y and z overlap); [12, 12.1] x [0, 0.1] x [1, 1.1] is
    // (1.5, 0, 0.5) away: sqrt(2.5) = 1.58; [1, 1.1] x ... is 8.4 away.
    // Answer 0.4; witnesses x = 9.5 on the box, x = 9.1 on the cell.
    const std::unique_ptr<Scene> tree = drone_tree();
    const opx_distance_result r = run("#640 1 m box at (10, 0, 0)", *tree, box_robot(1.0, Vec3(10, 0, 0)), 0.4, query);
    expect(std::abs(r.point_on_link[0] - 9.5) <= 1e-9 && std::abs(r.point_on_cell[0] - 9.1) <= 1e-9,
           "#640: witnesses at x = 9.5 (box) and x = 9.1 (cell)");
}

void issue_639(opx_query *query) {
    // Box [9.5, 10.5] x [-0.5, 0.5] x [4.5, 5.5].  Cell [12, 12.1] x [0, 0.1]
    // x [1, 1.1]: dx = 12 - 10.5 = 1.5, dy = 0, dz = 4.5 - 1.1 = 3.4, so
    // sqrt(1.5^2 + 3.4^2) = sqrt(13.81) = 3.71618...  Cell [9, 9.1] x [0, 0.1]^2:
    // (0.4, 0, 4.4), sqrt(19.52) = 4.418; cell [1, 1.1] x ...: farther.  The
    // witnesses: the box edge x = 10.5, z = 4.5 and the cell edge x = 12,
    // z = 1.1, at the same y in [0, 0.1].
    const std::unique_ptr<Scene> tree = drone_tree();
    const opx_distance_result r =
        run("#639 1 m box at (10, 0, 5)", *tree, box_robot(1.0, Vec3(10, 0, 5)), std::sqrt(13.81), query);
    const Vec3 a = vec(r.point_on_link), b = vec(r.point_on_cell);
    expect(std::abs(a.x() - 10.5) <= 1e-9 && std::abs(a.z() - 4.5) <= 1e-9 && std::abs(b.x() - 12) <= 1e-9 &&
               std::abs(b.z() - 1.1) <= 1e-9 && std::abs(a.y() - b.y()) <= 1e-9 && a.y() >= -1e-9 && a.y() <= 0.1 + 1e-9,
           "#639: witnesses on the box edge (10.5, y, 4.5) and the cell edge (12, y, 1.1)");
}

void issue_504(opx_query *query) {
    // Cell [1, 1.1] x [0, 0.1]^2.  A 0.1 m box at the origin, [-0.05, 0.05]^3:
    // 1 - 0.05 = 0.95 along x, y and z overlap.  At (2, 0, 0), [1.95, 2.05]:
    // 1.95 - 1.1 = 0.85.  point_on_link must be the box's point.
    const std::unique_ptr<Scene> tree = cells_scene(0.1, {Vec3(1, 0, 0)}, false);
    struct Case { double x, expected, link_x, cell_x; };
    for (const Case &c : {Case{0.0, 0.95, 0.05, 1.0}, Case{2.0, 0.85, 1.95, 1.1}}) {
        const std::string name = "#504 0.1 m box at (" + std::to_string(c.x) + ", 0, 0)";
        const opx_distance_result r = run(name, *tree, box_robot(0.1, Vec3(c.x, 0, 0)), c.expected, query);
        expect(std::abs(r.point_on_link[0] - c.link_x) <= 1e-9 && std::abs(r.point_on_cell[0] - c.cell_x) <= 1e-9,
               name + ": point_on_link is the box's point, point_on_cell the cell's (not reversed)");
    }
}

void issue_508(opx_query *query) {
    // The map box [-h, h]^3 (h = 0.5 or 1) and a link box of the same edge 2h
    // at distance t along one axis: the gap is t - 2h.  The issue's case is
    // h = 0.5, t = 4 along y: 3.0.
    for (double h : {0.5, 1.0}) {
        const double r = h;  // 8 cells of edge h fill [-h, h]^3
        std::vector<Vec3> corners;
        for (int i = 0; i < 8; ++i) corners.push_back(Vec3(i & 1 ? 0.5 : -0.5, i & 2 ? 0.5 : -0.5, i & 4 ? 0.5 : -0.5) * h);
        const std::unique_ptr<Scene> map = cells_scene(r, corners, false);
        expect(map->leaves.size() == 8, "#508: the map box is 8 cells");
        for (double t : {2 * h + 1e-3, 3 * h, 3.98 * h, 4 * h, 5 * h, 8 * h, 20 * h})
            for (int axis = 0; axis < 3; ++axis)
                for (double sign : {1.0, -1.0}) {
                    const Vec3 position = Vec3::Unit(axis) * (sign * t);
                    char name[96];
                    std::snprintf(name, sizeof name, "#508 %g m boxes, offset %+g along %c", 2 * h, sign * t, "xyz"[axis]);
                    run(name, *map, box_robot(2 * h, position), t - 2 * h, query);
                }
    }
}

}  // namespace

int main() {
    elapsed_seconds();
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    issue_640(query);
    issue_639(query);
    issue_504(query);
    issue_508(query);
    opx_query_destroy(query);
    std::printf("SUMMARY oracle_fcl_issues: queries %d, mismatches %d, max error %.3g m; %.1f s\n", cases, failures,
                max_error, elapsed_seconds());
    return failures == 0 ? 0 : 1;
}
