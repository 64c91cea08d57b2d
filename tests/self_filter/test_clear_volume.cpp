// Part of self_filter_edges (see test_self_filter_edges.cpp):
// clear_robot_volume against the brute force, two frames (the ghost of an
// obstacle where the arm then stands); attached objects and disabled links.
#include "filter_helpers.hpp"
#include "filter_oracle.hpp"
#include "filter_scenes.hpp"

#include "oracle_geometry.hpp"
#include "real_support.hpp"

#include <cmath>
#include <set>

namespace {

using filter_oracle::Vec3;
using Key = std::array<int64_t, 3>;

constexpr double kKeyCenter = 32768.0;  // OctoMap's tree_max_val

Vec3 corner_of(const Key &k, double res) {
    return Vec3((k[0] - kKeyCenter) * res, (k[1] - kKeyCenter) * res, (k[2] - kKeyCenter) * res);
}

uint64_t pack(const Key &k) { return uint64_t(k[0]) | (uint64_t(k[1]) << 16) | (uint64_t(k[2]) << 32); }

// Whether the cell's closed cube lies inside the solid: every corner inside
// (enough for a convex solid); for a closed mesh also no triangle meeting it.
bool cell_inside(const filter_oracle::Solid &solid, const Key &k, double res) {
    for (int c = 0; c < 8; ++c)
        if (solid.distance(corner_of(Key{k[0] + (c & 1), k[1] + ((c >> 1) & 1), k[2] + (c >> 2)}, res)) != 0.0)
            return false;
    if (!solid.surface || solid.kind != OPX_SHAPE_MESH) return true;
    const oracle::Cell cell{corner_of(k, res) + Vec3::Constant(0.5 * res), 0.5 * res};
    for (const oracle::Triangle &t : solid.surface->triangles())
        if (oracle::triangle_cell_distance(t, cell) == 0.0) return false;
    return true;
}

// The cells entirely inside some unpadded solid: brute force over the cells
// meeting each solid's bounding ball.
std::set<uint64_t> cells_inside(const filter_oracle::OracleRobot &oracle, double res) {
    std::set<uint64_t> cells;
    for (const filter_oracle::Solid &solid : oracle.solids()) {
        Key lo, hi;
        for (int a = 0; a < 3; ++a) {
            lo[a] = int64_t(std::floor((solid.center[a] - solid.bound) / res) + kKeyCenter);
            hi[a] = int64_t(std::floor((solid.center[a] + solid.bound) / res) + kKeyCenter);
        }
        for (int64_t x = lo[0]; x <= hi[0]; ++x)
            for (int64_t y = lo[1]; y <= hi[1]; ++y)
                for (int64_t z = lo[2]; z <= hi[2]; ++z)
                    if (cell_inside(solid, Key{x, y, z}, res)) cells.insert(pack(Key{x, y, z}));
    }
    return cells;
}

// Points filling the unpadded solids, spaced half a cell apart.
std::vector<Vec3> obstacle_points(const filter_oracle::OracleRobot &oracle, double res) {
    std::vector<Vec3> points;
    for (const filter_oracle::Solid &solid : oracle.solids())
        for (double x = -solid.bound; x <= solid.bound; x += res / 2)
            for (double y = -solid.bound; y <= solid.bound; y += res / 2)
                for (double z = -solid.bound; z <= solid.bound; z += res / 2)
                    if (solid.distance(solid.center + Vec3(x, y, z)) == 0.0)
                        points.push_back(solid.center + Vec3(x, y, z));
    return points;
}

std::set<uint64_t> cells_at(const real::FineCells &cells, float value) {
    std::set<uint64_t> out;
    for (const auto &cell : cells)
        if (cell.second == value) out.insert(cell.first);
    return out;
}

void ghost_at(double res) {
    opx_linkset *arm = filter_oracle::make_arm(1);
    filter_oracle::FilterSettings unpadded;
    const filter_oracle::OracleRobot oracle(arm, unpadded);
    const std::set<uint64_t> expected = cells_inside(oracle, res);
    const std::vector<Vec3> obstacle = obstacle_points(oracle, res);
    const Vec3 sensor(-0.8, -1.2, 1.6), far_sensor(-1.0, -1.0, 2.0);
    filter_oracle::FilterRequest none, keep, clear;
    keep.robot = clear.robot = arm;
    keep.robot_padding = clear.robot_padding = 0.02;
    clear.clear_robot_volume = true;
    opx_octree *kept = real::new_octree(res), *cleared = real::new_octree(res);
    filter_oracle::insert_seen_from(kept, none, sensor, obstacle);  // the obstacle, before the arm came
    filter_oracle::insert_seen_from(cleared, none, sensor, obstacle);
    const std::vector<Vec3> away = {Vec3(-1.5, -1.5, 2.2)};        // a frame that sees nothing of the arm
    filter_oracle::insert_seen_from(kept, keep, far_sensor, away);
    const opx_insert_report r = filter_oracle::insert_seen_from(cleared, clear, far_sensor, away);
    const float clamp = octomap::OcTree(res).getClampingThresMinLog();
    const real::FineCells after = real::expand_octoprox(cleared), kept_cells = real::expand_octoprox(kept);
    const std::set<uint64_t> got = cells_at(after, clamp);
    size_t ghost_cells = 0, partly_inside = 0;
    for (const uint64_t key : expected) {
        const auto it = kept_cells.find(key);
        ghost_cells += it != kept_cells.end() && it->second > 0.0f;  // an obstacle cell inside the arm, kept
    }
    for (const auto &cell : after) partly_inside += cell.second > 0.0f;  // obstacle cells the flag left
    print_message("%g cm: %zu cells entirely inside the arm's solids (brute force), %zu cleared (report %llu); "
                  "%zu of them held the obstacle and stay occupied without the flag; %zu obstacle cells only "
                  "partly inside stay occupied\n",
                  res * 100, expected.size(), got.size(), (unsigned long long)r.cells_cleared, ghost_cells,
                  partly_inside);
    if (got != expected) {
        size_t missing = 0, extra = 0;
        for (uint64_t k : expected) missing += got.count(k) == 0;
        for (uint64_t k : got) extra += expected.count(k) == 0;
        fail_msg("%g cm: cleared cells differ from the brute force: %zu not cleared, %zu cleared but not inside",
                 res * 100, missing, extra);
    }
    assert_int_equal(r.cells_cleared, expected.size());
    assert_true(ghost_cells > 0);
    for (uint32_t threads : {2u, 0u}) {  // the same bytes on more threads
        opx_octree *again = real::new_octree(res);
        filter_oracle::insert_seen_from(again, none, sensor, obstacle);
        clear.max_threads = threads;
        filter_oracle::insert_seen_from(again, clear, far_sensor, away);
        assert_true(filter_oracle::saved_bytes(again) == filter_oracle::saved_bytes(cleared));
        opx_octree_destroy(again);
    }
    opx_octree_destroy(kept);
    opx_octree_destroy(cleared);
    opx_linkset_destroy(arm);
}

}  // namespace

void test_clear_robot_volume(void **) {
    ghost_at(0.02);
    ghost_at(0.01);
}

// A sensor inside a padded sphere (a camera in its housing): the sphere
// shadows nothing; a point inside it is a robot point whose ray carves
// nothing; a point beyond it is kept, its ray carving through the sphere.
void test_sensor_inside_a_solid(void **) {
    opx_shape ball = OPX_SHAPE_INIT;
    ball.kind = OPX_SHAPE_SPHERE, ball.radius = 0.1;
    const opx_pose identity = OPX_POSE_IDENTITY;
    opx_linkset *robot = filter_oracle::one_link(ball, identity);
    filter_oracle::FilterRequest request;
    request.robot = robot, request.robot_padding = 0.02;
    const Vec3 sensor(0.013, -0.021, 0.007);
    opx_octree *tree = real::new_octree(0.02);
    opx_insert_report r = filter_oracle::insert_seen_from(tree, request, sensor, {Vec3(0.09, 0.03, 0.0)});
    assert_int_equal(r.points_on_robot, 1);
    assert_int_equal(r.cells_missed + r.cells_hit, 0);
    assert_int_equal(real::expand_octoprox(tree).size(), 0);
    r = filter_oracle::insert_seen_from(tree, request, sensor, {Vec3(0.6, 0.05, 0.02)});
    assert_int_equal(r.points_used, 1);
    const real::FineCells cells = real::expand_octoprox(tree);
    size_t inside_ball = 0, occupied = 0;
    for (const auto &cell : cells) {
        const Vec3 centre(((cell.first & 0xffff) - kKeyCenter + 0.5) * 0.02,
                          (((cell.first >> 16) & 0xffff) - kKeyCenter + 0.5) * 0.02,
                          ((cell.first >> 32) - kKeyCenter + 0.5) * 0.02);
        inside_ball += centre.norm() < 0.1 && cell.second < 0.0f;
        occupied += cell.second > 0.0f;
    }
    assert_true(inside_ball >= 3);  // the ray carved free cells inside the padded sphere
    assert_int_equal(occupied, 1);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}

// A sphere attached to a link without shapes filters as a link's would;
// a disabled link filters nothing, nor its attached objects.
void test_attached_and_disabled(void **) {
    opx_linkset *robot = nullptr;
    real::check_ok(opx_linkset_create(&robot), "opx_linkset_create");
    real::check_ok(opx_linkset_add_link(robot, "holder", nullptr), "opx_linkset_add_link");
    opx_shape ball = OPX_SHAPE_INIT;
    ball.kind = OPX_SHAPE_SPHERE, ball.radius = 0.1;
    opx_pose at = OPX_POSE_IDENTITY;
    at.position[0] = 1.0;
    real::check_ok(opx_linkset_attach_object(robot, 0, "ball", &ball, 1, &at, nullptr, 0, nullptr), "attach");
    const opx_pose identity = OPX_POSE_IDENTITY;
    real::check_ok(opx_linkset_set_poses(robot, &identity, 1, 0), "opx_linkset_set_poses");
    // 1 cm beyond the padded ball, 1 cm inside it, behind it, elsewhere.
    const std::vector<Vec3> points = {Vec3(0.87, 0, 0), Vec3(0.89, 0, 0), Vec3(1.5, 0, 0), Vec3(0.5, 0.5, 0)};
    filter_oracle::FilterRequest request;
    request.robot = robot, request.robot_padding = 0.02;
    opx_octree *tree = real::new_octree(0.05);
    opx_insert_report r = filter_oracle::insert_seen_from(tree, request, Vec3::Zero(), points);
    assert_int_equal(r.points_used, 2);
    assert_int_equal(r.points_on_robot, 1);
    assert_int_equal(r.points_shadowed, 1);
    real::check_ok(opx_linkset_set_link_enabled(robot, 0, 0), "opx_linkset_set_link_enabled");
    r = filter_oracle::insert_seen_from(tree, request, Vec3::Zero(), points);
    assert_int_equal(r.points_used, 4);
    opx_octree_destroy(tree);
    opx_linkset_destroy(robot);
}
