// self_filter_edges: the padded robot's edges, per solid kind, against the
// oracle's exact distances (no data needed):
//   - band edges: at random poses and random points of each solid's
//     surface (sphere, box, cylinder, capsule, convex hull, a closed
//     L-shaped mesh that is not convex, an open mesh as its hull), a point
//     at padding - 1e-6 m along the normal is a robot point, one at
//     padding + 1e-6 m is kept; points deep inside the closed mesh are
//     robot points;
//   - clear_robot_volume: an obstacle inserted where the robot then stands
//     is cleared with the flag and stays without it; the cleared cells are
//     exactly the cells entirely inside an unpadded solid (brute force over
//     the cells around each solid: all 8 corners inside, and for the mesh
//     no triangle meeting the cell);
//   - attached objects filter like links; disabled links filter nothing;
//   - a sensor inside a padded solid: it shadows nothing, a point in it
//     is a robot point whose ray carves nothing.
#include "band_samples.hpp"
#include "filter_helpers.hpp"
#include "filter_scenes.hpp"

#include "oracle_geometry.hpp"
#include "real_support.hpp"

#include <cmath>

namespace {

using filter_oracle::one_link;
using filter_oracle::Vec3;

constexpr double kRobotPadding = 0.02, kSetPadding = 0.003, kLinkPadding = 0.004;
constexpr double kEdge = 1e-6;
const char *const kKindNames[6] = {"cylinder", "capsule", "box", "convex hull", "closed mesh", "open mesh"};

opx_insert_report insert(opx_octree *tree, const opx_linkset *robot, const Vec3 &sensor,
                         const std::vector<Vec3> &points) {
    filter_oracle::FilterRequest request;
    request.robot = robot, request.robot_padding = kRobotPadding;
    return filter_oracle::insert_seen_from(tree, request, sensor, points);
}

// One sample: the pair of points across the band's edge, seen along the
// normal; false when the oracle finds the pair does not test the edge (a
// nearer part of a mesh that is not convex).
bool check_edge_pair(const filter_oracle::OracleRobot &oracle, const opx_linkset *robot, opx_octree *tree,
                     const filter_oracle::SurfacePoint &s, double padding, const char *kind) {
    const Vec3 inner = s.point + (padding - kEdge) * s.normal, outer = s.point + (padding + kEdge) * s.normal;
    const Vec3 sensor = s.point + 0.4 * s.normal;
    const auto &solid = oracle.solids()[0];
    if (std::fabs(solid.distance(inner) - (padding - kEdge)) > 1e-10 ||
        std::fabs(solid.distance(outer) - (padding + kEdge)) > 1e-10)
        return false;
    const std::vector<filter_oracle::Verdict> v = oracle.judge_frame(sensor, {inner, outer});
    if (v[0].ambiguous || v[1].ambiguous || v[1].kind != filter_oracle::Verdict::kKept) return false;
    const opx_insert_report r = insert(tree, robot, sensor, {inner, outer});
    if (r.points_on_robot != 1 || r.points_used != 1 || r.points_shadowed != 0)
        fail_msg("%s: points at padding -+ 1e-6 from (%.9f %.9f %.9f) along (%.6f %.6f %.6f): on robot %llu, used "
                 "%llu, shadowed %llu (expected 1, 1, 0)",
                 kind, s.point.x(), s.point.y(), s.point.z(), s.normal.x(), s.normal.y(), s.normal.z(),
                 (unsigned long long)r.points_on_robot, (unsigned long long)r.points_used,
                 (unsigned long long)r.points_shadowed);
    return true;
}

void band_edges_of(const opx_shape &shape, const char *kind, std::mt19937 &rng) {
    size_t tested = 0, skipped = 0;
    const double padding = kRobotPadding + kSetPadding + kLinkPadding;
    for (int trial = 0; trial < 4; ++trial) {
        opx_linkset *robot = one_link(shape, filter_oracle::random_pose(rng, Vec3(0.3, -0.2, 0.8), 0.5));
        real::check_ok(opx_linkset_set_padding(robot, kSetPadding), "opx_linkset_set_padding");
        real::check_ok(opx_linkset_set_link_padding(robot, 0, kLinkPadding), "opx_linkset_set_link_padding");
        filter_oracle::FilterSettings settings;
        settings.robot_padding = kRobotPadding, settings.link_padding = {kSetPadding + kLinkPadding};
        const filter_oracle::OracleRobot oracle(robot, settings);
        opx_octree *tree = real::new_octree(0.05);
        for (int sample = 0; sample < 30; ++sample) {
            const filter_oracle::SurfacePoint s = filter_oracle::random_surface_point(oracle.solids()[0], rng);
            (check_edge_pair(oracle, robot, tree, s, padding, kind) ? tested : skipped) += 1;
        }
        opx_octree_destroy(tree);
        opx_linkset_destroy(robot);
    }
    print_message("%s: %zu pairs across the band's edge (padding %.3f m) sorted right, %zu samples skipped\n", kind,
                  tested, padding, skipped);
    assert_true(tested >= 80);
}

void test_band_edges(void **) {
    std::mt19937 rng(20261207);
    opx_shape sphere = OPX_SHAPE_INIT;
    sphere.kind = OPX_SHAPE_SPHERE, sphere.radius = 0.1;
    band_edges_of(sphere, "sphere", rng);
    for (int link = 0; link < 6; ++link) band_edges_of(filter_oracle::arm_link_shape(link), kKindNames[link], rng);
}

// Points 5 mm inside the closed mesh's walls (3 cm thick) are robot points.
void test_deep_inside_the_closed_mesh(void **) {
    std::mt19937 rng(5);
    const opx_pose pose = filter_oracle::random_pose(rng, Vec3(1, 0, 0), 0.1);
    opx_linkset *robot = one_link(filter_oracle::arm_link_shape(4), pose);
    filter_oracle::FilterSettings settings;
    settings.robot_padding = kRobotPadding;
    const filter_oracle::OracleRobot oracle(robot, settings);
    std::vector<Vec3> inside;
    while (inside.size() < 200) {
        const filter_oracle::SurfacePoint s = filter_oracle::random_surface_point(oracle.solids()[0], rng);
        const Vec3 p = s.point - 0.005 * s.normal;
        if (oracle.solids()[0].distance(p) == 0.0) inside.push_back(p);
    }
    opx_octree *tree = real::new_octree(0.02);
    const opx_insert_report r = insert(tree, robot, Vec3(-1, 0.2, 0.1), inside);
    assert_int_equal(r.points_on_robot, inside.size());
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

}  // namespace

void test_clear_robot_volume(void **);
void test_attached_and_disabled(void **);
void test_sensor_inside_a_solid(void **);

int main() {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_band_edges),
                                       cmocka_unit_test(test_deep_inside_the_closed_mesh),
                                       cmocka_unit_test(test_clear_robot_volume),
                                       cmocka_unit_test(test_attached_and_disabled),
                                       cmocka_unit_test(test_sensor_inside_a_solid)};
    return cmocka_run_group_tests(tests, nullptr, nullptr);
}
