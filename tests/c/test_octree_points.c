/*
 * Point input of opx_octree_insert_points: float32 and float64, packed and
 * strided (ROS PointCloud2-like records, unaligned strides), and the sensor
 * pose that takes sensor-frame points into the map frame.
 */
#include "opx_test.h"

#define N_POINTS 4
/* Sensor-frame points, exact in float; with the sensor at (C0, C0, C0)
 * every endpoint is a cell centre. */
static const double XYZ[N_POINTS][3] = {
    {1.0, 0.0, 0.0}, {0.0, 1.5, 0.0}, {-0.75, 0.5, 0.25}, {0.5, -1.25, 1.0}};

/* The leaves of a fresh map after inserting `points` once. */
static opx_leaf *leaves_after_insert(const void *points, size_t stride, int32_t scalar,
                                     size_t *out_count) {
    opx_octree *tree = new_tree(RES);
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    assert_ok(opx_octree_insert_points(tree, points, N_POINTS, stride, scalar, &options, &report));
    assert_int_equal(report.points_used, N_POINTS);
    assert_int_equal(report.cells_hit, N_POINTS);
    opx_leaf *leaves = all_leaves(tree, OPX_MASK_ALL_KNOWN, out_count);
    opx_octree_destroy(tree);
    return leaves;
}

/* The reference: packed float64. */
static opx_leaf *reference_leaves(size_t *out_count) {
    return leaves_after_insert(XYZ, 0, OPX_SCALAR_FLOAT64, out_count);
}

static void assert_same_as_reference(const opx_leaf *leaves, size_t count) {
    size_t ref_count = 0;
    opx_leaf *ref = reference_leaves(&ref_count);
    assert_true(ref_count > N_POINTS); /* hits and free cells */
    assert_same_leaves(leaves, count, ref, ref_count);
    free(ref);
}

static void float64_with_explicit_stride_equals_packed(void **state) {
    (void)state;
    size_t count = 0;
    opx_leaf *leaves = leaves_after_insert(XYZ, 3 * sizeof(double), OPX_SCALAR_FLOAT64, &count);
    assert_same_as_reference(leaves, count);
    free(leaves);
}

static void float32_packed_equals_float64(void **state) {
    (void)state;
    float xyz[N_POINTS][3];
    for (int i = 0; i < N_POINTS; ++i)
        for (int a = 0; a < 3; ++a) xyz[i][a] = (float)XYZ[i][a];
    size_t count = 0;
    opx_leaf *leaves = leaves_after_insert(xyz, 0, OPX_SCALAR_FLOAT32, &count);
    assert_same_as_reference(leaves, count);
    free(leaves);
}

/* A PointCloud2-like record: x y z then rgba, stride 16. */
typedef struct xyz_rgba {
    float x, y, z;
    uint32_t rgba;
} xyz_rgba;

static void float32_records_with_stride_16(void **state) {
    (void)state;
    xyz_rgba cloud[N_POINTS];
    assert_int_equal(sizeof cloud[0], 16);
    for (int i = 0; i < N_POINTS; ++i) {
        cloud[i].x = (float)XYZ[i][0];
        cloud[i].y = (float)XYZ[i][1];
        cloud[i].z = (float)XYZ[i][2];
        cloud[i].rgba = 0xFFFFFFFFu; /* a NaN if it were read as a coordinate */
    }
    size_t count = 0;
    opx_leaf *leaves = leaves_after_insert(cloud, sizeof cloud[0], OPX_SCALAR_FLOAT32, &count);
    assert_same_as_reference(leaves, count);
    free(leaves);
}

/* Points `stride` bytes apart from `base`, which may be unaligned; the gap
 * bytes hold 0xFF (NaN patterns) so reading them would show. */
static void fill_unaligned(unsigned char *base, size_t stride, int32_t scalar) {
    memset(base, 0xFF, N_POINTS * stride);
    for (int i = 0; i < N_POINTS; ++i) {
        for (int a = 0; a < 3; ++a) {
            if (scalar == OPX_SCALAR_FLOAT32) {
                const float v = (float)XYZ[i][a];
                memcpy(base + i * stride + a * sizeof v, &v, sizeof v);
            } else {
                memcpy(base + i * stride + a * sizeof(double), &XYZ[i][a], sizeof(double));
            }
        }
    }
}

static void float32_unaligned_stride_13(void **state) {
    (void)state;
    unsigned char buffer[1 + N_POINTS * 13];
    fill_unaligned(buffer + 1, 13, OPX_SCALAR_FLOAT32);
    size_t count = 0;
    opx_leaf *leaves = leaves_after_insert(buffer + 1, 13, OPX_SCALAR_FLOAT32, &count);
    assert_same_as_reference(leaves, count);
    free(leaves);
}

static void float64_unaligned_stride_27(void **state) {
    (void)state;
    unsigned char buffer[3 + N_POINTS * 27];
    fill_unaligned(buffer + 3, 27, OPX_SCALAR_FLOAT64);
    size_t count = 0;
    opx_leaf *leaves = leaves_after_insert(buffer + 3, 27, OPX_SCALAR_FLOAT64, &count);
    assert_same_as_reference(leaves, count);
    free(leaves);
}

/* The minimum strides, 12 and 24 bytes, are a packed array. */
static void minimum_strides_are_accepted(void **state) {
    (void)state;
    float xyz[N_POINTS][3];
    for (int i = 0; i < N_POINTS; ++i)
        for (int a = 0; a < 3; ++a) xyz[i][a] = (float)XYZ[i][a];
    size_t count = 0;
    opx_leaf *leaves = leaves_after_insert(xyz, 12, OPX_SCALAR_FLOAT32, &count);
    assert_same_as_reference(leaves, count);
    free(leaves);
    leaves = leaves_after_insert(XYZ, 24, OPX_SCALAR_FLOAT64, &count);
    assert_same_as_reference(leaves, count);
    free(leaves);
}

/* Sensor rotated 90 degrees about z at (C0, C0, C0): sensor-frame (1, 0, 0)
 * lands at map (C0, 1 + C0, C0), and the ray runs along map +y. */
static void sensor_pose_rotates_and_translates(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    options.sensor_pose.orientation[2] = sqrt(0.5); /* sin 45 deg */
    options.sensor_pose.orientation[3] = sqrt(0.5);
    const float point[3] = {1.0f, 0.0f, 0.0f};
    assert_ok(opx_octree_insert_points(tree, point, 1, 0, OPX_SCALAR_FLOAT32, &options, NULL));
    const opx_cell_info hit = classify_at(tree, C0, 1.0 + C0, C0);
    assert_int_equal(hit.cell_class, OPX_CELL_OCCUPIED);
    assert_near(hit.center[1], 1.0 + C0, OPX_GEOM_TOL);
    assert_int_equal(classify_at(tree, C0, 0.5 + C0, C0).cell_class, OPX_CELL_FREE);
    assert_int_equal(classify_at(tree, 1.0 + C0, C0, C0).cell_class, OPX_CELL_UNKNOWN);
    opx_octree_destroy(tree);
}

/* The quaternion is normalised: (0, 0, 2, 2) is the same 90 degrees. A
 * 180 degree turn about x maps sensor +y to map -y, +z to -z. */
static void quaternion_is_normalised_and_in_ros_order(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    opx_insert_options options = sensor_at(10.0 + C0, -5.0 + C0, 2.0 + C0, OPX_INSERT_ENDPOINTS);
    options.sensor_pose.orientation[2] = 2.0;
    options.sensor_pose.orientation[3] = 2.0;
    const double ahead[3] = {1.0, 0.0, 0.0};
    insert_f64(tree, ahead, 1, &options);
    assert_int_equal(classify_at(tree, 10.0 + C0, -4.0 + C0, 2.0 + C0).cell_class,
                     OPX_CELL_OCCUPIED);

    options.sensor_pose.orientation[0] = 1.0; /* x first: ROS order */
    options.sensor_pose.orientation[2] = 0.0;
    options.sensor_pose.orientation[3] = 0.0;
    const double up_left[3] = {0.0, 1.0, 2.0};
    insert_f64(tree, up_left, 1, &options);
    assert_int_equal(classify_at(tree, 10.0 + C0, -6.0 + C0, C0).cell_class, OPX_CELL_OCCUPIED);
    assert_int_equal(stats_of(tree).leaves_occupied, 2);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(float64_with_explicit_stride_equals_packed),
        cmocka_unit_test(float32_packed_equals_float64),
        cmocka_unit_test(float32_records_with_stride_16),
        cmocka_unit_test(float32_unaligned_stride_13),
        cmocka_unit_test(float64_unaligned_stride_27),
        cmocka_unit_test(minimum_strides_are_accepted),
        cmocka_unit_test(sensor_pose_rotates_and_translates),
        cmocka_unit_test(quaternion_is_normalised_and_in_ros_order),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
