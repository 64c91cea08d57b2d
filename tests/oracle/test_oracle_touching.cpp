// Touching and grazing cases, decided by the rule of query.h (closed sets):
// a shape collides with a cell when their distance is <= its inflation
// (padding, + radius for spheres and capsules) + 1e-9 m.  So:
//   - contact at distance 0 (a face flush with a cell face, an edge on an
//     edge, a corner on a corner, a sphere tangent to an edge or a corner, a
//     triangle lying in a cell face) COLLIDES;
//   - a gap of 1e-6 m does NOT (well above the 1e-9 tolerance);
//   - a padding exactly equal to the gap COLLIDES, 1e-6 m less does not;
//   - a cell exactly at the threshold (probability == threshold, the rule is
//     ">=") IS an obstacle, also when the threshold is the reported p;
//   - a closed mesh around a cell touches nothing (a surface), its convex
//     hull does (a solid).
// The map holds one cell, [0, 0.25]^3 (resolution 0.25: every coordinate
// below is exact in binary).  Each case states its expected answer; the
// library must give it, and the oracle too (unless it calls the pair
// ambiguous: cylinders within 1e-5 m of the threshold).
#include "oracle_engine.hpp"
#include "oracle_scenes.hpp"

#include <cstdio>

using namespace oracle;

namespace {

constexpr double kGap = 1e-6;

struct Case {
    const char *name;
    ShapeSpec shape;
    bool collides;
    double link_padding = 0.0, global_padding = 0.0;
    double threshold = 0.0;
    bool enabled = true;
};

ShapeSpec at(ShapeSpec s, double x, double y, double z) {
    s.pose.position[0] = x, s.pose.position[1] = y, s.pose.position[2] = z;
    return s;
}

ShapeSpec box(double sx, double sy, double sz) {
    ShapeSpec s;
    s.kind = OPX_SHAPE_BOX;
    s.size = Vec3(sx, sy, sz);
    return s;
}

ShapeSpec round_shape(int32_t kind, double radius, double length = 0.0) {
    ShapeSpec s;
    s.kind = kind;
    s.radius = radius, s.length = length;
    return s;
}

ShapeSpec rotated_about_y(ShapeSpec s) {  // the shape's z axis along the map's x
    const double half = std::sqrt(0.5);
    s.pose.orientation[1] = half, s.pose.orientation[3] = half;
    return s;
}

ShapeSpec tetrahedron(double x) {  // a face in the plane x, the apex at x - 0.5
    ShapeSpec s;
    s.kind = OPX_SHAPE_CONVEX;
    s.vertices = {Vec3(x, 0, 0), Vec3(x, 0.25, 0), Vec3(x, 0, 0.25), Vec3(x - 0.5, 0.1, 0.1)};
    s.hull_vertex_count = 4;
    s.hull_faces = {{0, 1, 2}, {0, 1, 3}, {0, 2, 3}, {1, 2, 3}};
    return s;
}

ShapeSpec triangle(double z) {  // in the plane z, over the cell
    ShapeSpec s;
    s.kind = OPX_SHAPE_MESH;
    s.vertices = {Vec3(-1, -1, z), Vec3(2, -1, z), Vec3(0.1, 2, z)};
    s.triangles = {{0, 1, 2}};
    return s;
}

// The cube [-0.5, 0.75]^3 around the cell, as a closed surface or a hull.
ShapeSpec cube_around(int32_t kind) {
    ShapeSpec s;
    s.kind = kind;
    for (int i = 0; i < 8; ++i)
        s.vertices.push_back(Vec3(i & 1 ? 0.75 : -0.5, i & 2 ? 0.75 : -0.5, i & 4 ? 0.75 : -0.5));
    const int quads[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
    for (const auto &q : quads) {
        s.triangles.push_back({uint32_t(q[0]), uint32_t(q[1]), uint32_t(q[2])});
        s.triangles.push_back({uint32_t(q[0]), uint32_t(q[2]), uint32_t(q[3])});
        s.hull_faces.push_back({q[0], q[1], q[2]});
        s.hull_faces.push_back({q[0], q[2], q[3]});
    }
    s.hull_vertex_count = 8;
    return s;
}

std::vector<Case> geometry_cases() {
    const double r_edge = 0.5;  // |(-0.3, -0.4)| = 0.5 exactly (3-4-5)
    const double r_corner = 0.6;  // |(-0.2, -0.4, -0.4)| = 0.6 (1-2-2)
    return {
        {"box face flush with the cell face", at(box(1, 0.25, 0.25), -0.5, 0.125, 0.125), true},
        {"box 1e-6 m from the cell face", at(box(1, 0.25, 0.25), -0.5 - kGap, 0.125, 0.125), false},
        {"box edge on the cell edge", at(box(1, 1, 0.25), -0.5, -0.5, 0.125), true},
        {"box corner on the cell corner", at(box(1, 1, 1), -0.5, -0.5, -0.5), true},
        {"box overlapping the cell", at(box(0.1, 0.1, 0.1), 0.1, 0.1, 0.1), true},
        {"sphere tangent to the cell face", at(round_shape(OPX_SHAPE_SPHERE, 0.5), 0.125, 0.125, 0.75), true},
        {"sphere 1e-6 m from the cell face", at(round_shape(OPX_SHAPE_SPHERE, 0.5 - kGap), 0.125, 0.125, 0.75),
         false},
        {"sphere tangent to the cell edge", at(round_shape(OPX_SHAPE_SPHERE, r_edge), -0.3, -0.4, 0.125), true},
        {"sphere 1e-6 m from the cell edge", at(round_shape(OPX_SHAPE_SPHERE, r_edge - kGap), -0.3, -0.4, 0.125),
         false},
        {"sphere tangent to the cell corner", at(round_shape(OPX_SHAPE_SPHERE, r_corner), -0.2, -0.4, -0.4), true},
        {"sphere 1e-6 m from the cell corner",
         at(round_shape(OPX_SHAPE_SPHERE, r_corner - kGap), -0.2, -0.4, -0.4), false},
        {"capsule tangent to the cell face", at(rotated_about_y(round_shape(OPX_SHAPE_CAPSULE, 0.125, 1)), 0.125,
                                                0.125, 0.375), true},
        {"capsule 1e-6 m from the cell face", at(rotated_about_y(round_shape(OPX_SHAPE_CAPSULE, 0.125, 1)), 0.125,
                                                 0.125, 0.375 + kGap), false},
        {"cylinder cap flush with the cell face", at(round_shape(OPX_SHAPE_CYLINDER, 0.1, 1), 0.125, 0.125, 0.75),
         true},
        {"cylinder cap 1e-6 m from the cell face",
         at(round_shape(OPX_SHAPE_CYLINDER, 0.1, 1), 0.125, 0.125, 0.75 + kGap), false},
        {"cylinder side tangent to the cell face", at(round_shape(OPX_SHAPE_CYLINDER, 0.5, 0.1), -0.5, 0.125, 0.125),
         true},
        {"cylinder side 1e-6 m from the cell face",
         at(round_shape(OPX_SHAPE_CYLINDER, 0.5, 0.1), -0.5 - kGap, 0.125, 0.125), false},
        {"hull face flush with the cell face", tetrahedron(0.0), true},
        {"hull face 1e-6 m from the cell face", tetrahedron(-kGap), false},
        {"triangle lying in the cell face", triangle(0.25), true},
        {"triangle 1e-6 m above the cell face", triangle(0.25 + kGap), false},
        {"closed mesh around the cell (a surface)", cube_around(OPX_SHAPE_MESH), false},
        {"its convex hull (a solid)", cube_around(OPX_SHAPE_CONVEX), true},
    };
}

std::vector<Case> padding_and_threshold_cases(double leaf_probability) {
    const ShapeSpec gap_box = at(box(0.875, 0.25, 0.25), -0.5625, 0.125, 0.125);  // x in [-1, -0.125]
    const ShapeSpec overlapping = at(box(0.1, 0.1, 0.1), 0.1, 0.1, 0.1);
    return {
        {"padding (link + global) exactly closes a 0.125 m gap", gap_box, true, 0.0625, 0.0625},
        {"padding 1e-6 m short of the gap", gap_box, false, 0.0625, 0.0625 - kGap},
        {"sphere radius + padding exactly reach the cell", at(round_shape(OPX_SHAPE_SPHERE, 0.25), -0.375, 0.125,
                                                              0.125), true, 0.125},
        {"disabled link overlapping the cell", overlapping, false, 0.0, 0.0, 0.0, false},
        {"threshold 0.7, the cell's hit probability", overlapping, true, 0.0, 0.0, 0.7},
        {"threshold == the cell's reported probability", overlapping, true, 0.0, 0.0, leaf_probability},
        {"threshold 1e-6 above the cell's probability", overlapping, false, 0.0, 0.0, leaf_probability + 1e-6},
    };
}

// The library against the expectation, then the full oracle comparison.
bool run_case(const Case &c, const Scene &scene, opx_query *query, Checker &checker) {
    RobotSpec robot;
    robot.global_padding = c.global_padding;
    robot.links.push_back({c.name, {c.shape}, c.link_padding, c.enabled, OPX_POSE_IDENTITY});
    opx_linkset *links = build_linkset(robot);
    opx_collision_request request = OPX_COLLISION_REQUEST_INIT;
    request.occupancy_threshold = c.threshold;
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    const bool ok = opx_query_collide(query, scene.tree, links, &request, &result) == OPX_OK &&
                    bool(result.collided) == c.collides;
    std::printf("%-55s expected %-11s library %s\n", c.name, c.collides ? "collision" : "clear",
                result.collided ? "collision" : "clear");
    if (!ok) checker.fail(std::string(c.name) + ": the library says " + (result.collided ? "collision" : "clear"));
    const std::vector<PlacedShape> placed = place_robot(robot);
    const ObstacleRule rule(c.threshold > 0 ? c.threshold : scene.options.occupied_threshold, OPX_UNKNOWN_FREE);
    const OracleAnswer oracle = oracle_collide(placed, *scene.cells, rule);
    if (oracle.ambiguous.empty() && oracle.touching.empty() == c.collides)
        checker.fail(std::string(c.name) + ": the oracle disagrees with the expectation");
    QueryCase q;
    q.robot = &robot, q.placed = &placed, q.cells = scene.cells.get();
    q.resolution = scene.options.resolution, q.occupied_threshold = scene.options.occupied_threshold;
    q.threshold = c.threshold, q.label = c.name;
    checker.check(query, scene.tree, links, q);
    opx_linkset_destroy(links);
    return ok;
}

}  // namespace

int main() {
    elapsed_seconds();
    Scene scene;
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = 0.25;
    if (opx_octree_create(&options, &scene.tree) != OPX_OK) return 1;
    insert_frame(scene.tree, {Vec3(0.1, 0.1, 0.1)}, opx_pose OPX_POSE_IDENTITY, OPX_INSERT_ENDPOINTS);
    scene.label = "one cell [0, 0.25]^3";
    index_scene(scene, false);
    if (scene.leaves.size() != 1 || scene.leaves[0].size != 0.25 || scene.leaves[0].center[0] != 0.125) {
        std::printf("FAIL: the map is not the single cell [0, 0.25]^3\n");
        return 1;
    }
    Checker checker("oracle_touching");
    opx_query *query = nullptr;
    if (oracle_create_query(&query) != OPX_OK) return 1;
    for (const Case &c : geometry_cases()) run_case(c, scene, query, checker);
    for (const Case &c : padding_and_threshold_cases(scene.leaves[0].probability)) run_case(c, scene, query, checker);
    opx_query_destroy(query);
    return checker.finish(elapsed_seconds());
}
