// real_rgbd_vs_octomap: a real Kinect frame inserted by OctoProx and by
// OctoMap's own insertPointCloud must give the same map, cell by cell, with
// identical float log-odds.
#include "real_support.hpp"

#include "pcd_reader.h"

#include <Eigen/Geometry>

#include <cmath>
#include <cstring>

namespace {

constexpr size_t kFramePoints = 307200, kFiniteFramePoints = 271575;
pcd_cloud g_frame;

struct Pose {
    double position[3];
    double quaternion_xyzw[4];
};
const Pose kIdentity = {{0, 0, 0}, {0, 0, 0, 1}};

opx_insert_report insert_frame(opx_octree *tree, int32_t mode, const Pose &pose, double max_range) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.mode = mode;
    std::memcpy(options.sensor_pose.position, pose.position, sizeof pose.position);
    std::memcpy(options.sensor_pose.orientation, pose.quaternion_xyzw, sizeof pose.quaternion_xyzw);
    options.max_range = max_range;
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    real::check_ok(opx_octree_insert_points(tree, g_frame.xyz, g_frame.count, 0, OPX_SCALAR_FLOAT32, &options, &report),
                   "opx_octree_insert_points");
    const uint64_t accounted = report.points_used + report.points_nonfinite + report.points_out_of_range +
                               report.points_outside_map;
    assert_int_equal(accounted, g_frame.count);
    return report;
}

octomap::point3d map_origin(const Pose &pose) {
    return octomap::point3d(static_cast<float>(pose.position[0]), static_cast<float>(pose.position[1]),
                            static_cast<float>(pose.position[2]));
}

// The frame's finite points within max_range (<= 0: all), moved to the map
// frame in double (the way the library documents it) and rounded to float.
octomap::Pointcloud map_frame_cloud(const Pose &pose, double max_range) {
    const double *q = pose.quaternion_xyzw;
    const Eigen::Matrix3d rotation = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
    const Eigen::Vector3d translation(pose.position[0], pose.position[1], pose.position[2]);
    octomap::Pointcloud cloud;
    for (size_t i = 0; i < g_frame.count; ++i) {
        const float *p = &g_frame.xyz[3 * i];
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
        const Eigen::Vector3d map = rotation * Eigen::Vector3d(p[0], p[1], p[2]) + translation;
        const octomap::point3d point(static_cast<float>(map.x()), static_cast<float>(map.y()),
                                     static_cast<float>(map.z()));
        // OctoMap's range test, in float.
        if (max_range > 0 && !((point - map_origin(pose)).norm() <= max_range)) continue;
        cloud.push_back(point);
    }
    return cloud;
}

// OctoMap's reference insert; returns the sizes of its hit and miss sets.
void reference_raycast(octomap::OcTree &tree, const Pose &pose, double max_range, size_t *hits, size_t *misses) {
    const octomap::Pointcloud cloud = map_frame_cloud(pose, -1.0);
    octomap::KeySet free_cells, occupied_cells;
    tree.computeUpdate(cloud, map_origin(pose), free_cells, occupied_cells, max_range);
    *hits = occupied_cells.size();
    *misses = free_cells.size();
    tree.insertPointCloud(cloud, map_origin(pose), max_range, false, false);
}

void assert_same_map(const char *label, const opx_octree *ours, const octomap::OcTree &theirs) {
    const real::CellComparison c = real::compare_cells(real::expand_octoprox(ours), real::expand_octomap(theirs));
    real::print_comparison(label, c);
    assert_true(c.common > 0);
    assert_true(c.identical());
}

void check_raycast_identity(double resolution) {
    opx_octree *ours = real::new_octree(resolution);
    const opx_insert_report report = insert_frame(ours, OPX_INSERT_RAYCAST, kIdentity, -1.0);
    assert_int_equal(report.points_used, kFiniteFramePoints);
    assert_int_equal(report.points_nonfinite, kFramePoints - kFiniteFramePoints);
    assert_int_equal(report.points_out_of_range + report.points_outside_map, 0);
    octomap::OcTree theirs(resolution);
    size_t hits = 0, misses = 0;
    reference_raycast(theirs, kIdentity, -1.0, &hits, &misses);
    assert_int_equal(report.cells_hit, hits);
    assert_int_equal(report.cells_missed, misses);
    assert_same_map(resolution > 0.03 ? "ray-cast, identity, 5 cm" : "ray-cast, identity, 2 cm", ours, theirs);
    opx_octree_destroy(ours);
}

void test_raycast_identity_5cm(void **) { check_raycast_identity(0.05); }
void test_raycast_identity_2cm(void **) { check_raycast_identity(0.02); }

void test_endpoints_identity(void **) {
    opx_octree *ours = real::new_octree(0.05);
    const opx_insert_report report = insert_frame(ours, OPX_INSERT_ENDPOINTS, kIdentity, -1.0);
    octomap::OcTree theirs(0.05);
    octomap::KeySet endpoint_cells;
    for (const octomap::point3d &p : map_frame_cloud(kIdentity, -1.0)) endpoint_cells.insert(theirs.coordToKey(p));
    for (const octomap::OcTreeKey &key : endpoint_cells) theirs.updateNode(key, true, false);
    assert_int_equal(report.cells_hit, endpoint_cells.size());
    assert_int_equal(report.cells_missed, 0);
    assert_same_map("endpoints, identity, 5 cm", ours, theirs);
    opx_octree_destroy(ours);
}

// Points beyond max_range give no hit, and, as in OctoMap, their rays are
// cut at max_range and free the cells up to there.
void test_max_range(void **) {
    const double max_range = 1.2, resolution = 0.05;
    opx_octree *ours = real::new_octree(resolution);
    const opx_insert_report report = insert_frame(ours, OPX_INSERT_RAYCAST, kIdentity, max_range);
    const size_t in_range = map_frame_cloud(kIdentity, max_range).size();
    assert_int_equal(report.points_used, in_range);
    assert_int_equal(report.points_out_of_range, kFiniteFramePoints - in_range);
    assert_true(report.points_out_of_range > 0);
    const double slack = 0.5 * std::sqrt(3.0) * resolution;  // centre to corner of a cell
    for (const opx_leaf &leaf : real::get_leaves(ours, OPX_MASK_OCCUPIED)) {
        const double distance = std::sqrt(leaf.center[0] * leaf.center[0] + leaf.center[1] * leaf.center[1] +
                                          leaf.center[2] * leaf.center[2]);
        if (distance > max_range + slack) fail_msg("occupied cell at %.3f m, beyond %.2f m", distance, max_range);
    }
    octomap::OcTree theirs(resolution);
    size_t hits = 0, misses = 0;
    reference_raycast(theirs, kIdentity, max_range, &hits, &misses);
    assert_int_equal(report.cells_hit, hits);
    assert_int_equal(report.cells_missed, misses);
    assert_same_map("ray-cast, max range 1.2 m, 5 cm", ours, theirs);
    print_message("max range 1.2 m: %llu points used, %llu beyond range\n", (unsigned long long)report.points_used,
                  (unsigned long long)report.points_out_of_range);
    opx_octree_destroy(ours);
}

// Two frames accumulate log-odds exactly as two OctoMap inserts do.
void test_two_frames_accumulate(void **) {
    const Pose moved = {{0.10, -0.05, 0.02}, {0, 0, 0, 1}};  // the camera moved a little
    opx_octree *ours = real::new_octree(0.05);
    insert_frame(ours, OPX_INSERT_RAYCAST, kIdentity, -1.0);
    insert_frame(ours, OPX_INSERT_RAYCAST, moved, -1.0);
    octomap::OcTree theirs(0.05);
    size_t hits = 0, misses = 0;
    reference_raycast(theirs, kIdentity, -1.0, &hits, &misses);
    reference_raycast(theirs, moved, -1.0, &hits, &misses);
    assert_same_map("two frames accumulated, 5 cm", ours, theirs);
    opx_octree_destroy(ours);
}

// A rotated and translated sensor.  The library transforms in double and
// rounds to float once; so does this test.  Only a transform formula that
// differs in the last bit of a double could ever disagree, and only on a
// point within ~1e-16 m of a float rounding tie that is also on a cell
// boundary: so agreement is expected to be exact, and is asserted.
void test_rotated_pose(void **) {
    // Roughly a head camera (optical frame) looking along map +x, pitched
    // and yawed; the quaternion is deliberately not quite unit length.
    const Pose pose = {{0.30, -0.20, 1.10}, {-0.52, 0.48, -0.47, 0.52}};
    opx_octree *ours = real::new_octree(0.05);
    const opx_insert_report report = insert_frame(ours, OPX_INSERT_RAYCAST, pose, -1.0);
    assert_int_equal(report.points_used, kFiniteFramePoints);
    octomap::OcTree theirs(0.05);
    size_t hits = 0, misses = 0;
    reference_raycast(theirs, pose, -1.0, &hits, &misses);
    assert_int_equal(report.cells_hit, hits);
    assert_int_equal(report.cells_missed, misses);
    assert_same_map("ray-cast, rotated pose, 5 cm", ours, theirs);
    opx_octree_destroy(ours);
}

}  // namespace

int main() {
    const std::string path = real::require_data_file("rgbd/frame_20121214T142255.814212_binary.pcd");
    char error[512];
    if (pcd_read_file(path.c_str(), &g_frame, error, sizeof error) != 0) {
        std::fprintf(stderr, "%s\n", error);
        return 1;
    }
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_raycast_identity_5cm),
        cmocka_unit_test(test_raycast_identity_2cm),
        cmocka_unit_test(test_endpoints_identity),
        cmocka_unit_test(test_max_range),
        cmocka_unit_test(test_two_frames_accumulate),
        cmocka_unit_test(test_rotated_pose),
    };
    const int failures = cmocka_run_group_tests_name("real_rgbd_vs_octomap", tests, nullptr, nullptr);
    pcd_free(&g_frame);
    return failures;
}
