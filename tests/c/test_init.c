/*
 * The opx_x_init functions of every versioned struct: defaults equal to the
 * OPX_X_INIT macros, a smaller (older) size filled no further than that
 * size, and size 0 or NULL rejected.
 */
#include "opx_test.h"

#define SENTINEL 0xAB

/* Bytes [from, to) of p all hold the sentinel. */
static void assert_untouched(const void *p, size_t from, size_t to) {
    const unsigned char *bytes = p;
    for (size_t i = from; i < to; ++i)
        if (bytes[i] != SENTINEL) fail_msg("byte %zu was written (0x%02x)", i, bytes[i]);
}

/*
 * One test per struct type T, initialised by FN whose pointer argument is
 * named ARG in the header; PARTIAL is an older, smaller struct size.
 */
#define INIT_TESTS(T, FN, INIT, ARG, PARTIAL)                                                    \
    static void FN##_fills_the_defaults(void **state) {                                          \
        (void)state;                                                                             \
        const T expected = INIT;                                                                 \
        T value;                                                                                 \
        memset(&value, SENTINEL, sizeof value);                                                  \
        assert_ok(FN(&value, sizeof value));                                                     \
        assert_int_equal(value.struct_size, sizeof(T));                                          \
        assert_memory_equal(&value, &expected, sizeof value);                                    \
    }                                                                                            \
    static void FN##_writes_no_further_than_size(void **state) {                                 \
        (void)state;                                                                             \
        const T expected = INIT;                                                                 \
        T value;                                                                                 \
        memset(&value, SENTINEL, sizeof value);                                                  \
        assert_ok(FN(&value, PARTIAL));                                                          \
        assert_int_equal(value.struct_size, PARTIAL);                                            \
        assert_memory_equal((const char *)&value + sizeof(uint32_t),                             \
                            (const char *)&expected + sizeof(uint32_t),                          \
                            PARTIAL - sizeof(uint32_t));                                         \
        assert_untouched(&value, PARTIAL, sizeof value);                                         \
    }                                                                                            \
    /* A caller built against a newer header: the known fields get defaults. */                  \
    static void FN##_accepts_a_larger_size(void **state) {                                       \
        (void)state;                                                                             \
        const T expected = INIT;                                                                 \
        struct {                                                                                 \
            T value;                                                                             \
            unsigned char newer_fields[32];                                                      \
        } bigger;                                                                                \
        memset(&bigger, SENTINEL, sizeof bigger);                                                \
        assert_ok(FN(&bigger.value, sizeof bigger));                                             \
        assert_memory_equal((const char *)&bigger.value + sizeof(uint32_t),                      \
                            (const char *)&expected + sizeof(uint32_t),                          \
                            sizeof(T) - sizeof(uint32_t));                                       \
    }                                                                                            \
    static void FN##_rejects_bad_arguments(void **state) {                                       \
        (void)state;                                                                             \
        T value;                                                                                 \
        memset(&value, SENTINEL, sizeof value);                                                  \
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, #FN, ARG, FN(NULL, sizeof value));            \
        expect_failure(OPX_ERROR_VERSION, #FN, "size", FN(&value, 0));                           \
        assert_untouched(&value, 0, sizeof value);                                               \
        /* Too small to hold struct_size itself. */                                              \
        expect_failure(OPX_ERROR_VERSION, #FN, "size", FN(&value, 2));                           \
        assert_untouched(&value, 0, sizeof value);                                               \
    }

INIT_TESTS(opx_octree_options, opx_octree_options_init, OPX_OCTREE_OPTIONS_INIT, "options",
           offsetof(opx_octree_options, prob_hit))
INIT_TESTS(opx_insert_options, opx_insert_options_init, OPX_INSERT_OPTIONS_INIT, "options",
           offsetof(opx_insert_options, max_range))
INIT_TESTS(opx_insert_report, opx_insert_report_init, OPX_INSERT_REPORT_INIT, "report",
           offsetof(opx_insert_report, cells_hit))
INIT_TESTS(opx_depth_image, opx_depth_image_init, OPX_DEPTH_IMAGE_INIT, "image",
           offsetof(opx_depth_image, width))
INIT_TESTS(opx_camera_intrinsics, opx_camera_intrinsics_init, OPX_CAMERA_INTRINSICS_INIT,
           "intrinsics", offsetof(opx_camera_intrinsics, cx))
INIT_TESTS(opx_cell_info, opx_cell_info_init, OPX_CELL_INFO_INIT, "info",
           offsetof(opx_cell_info, center))
INIT_TESTS(opx_octree_stats, opx_octree_stats_init, OPX_OCTREE_STATS_INIT, "stats",
           offsetof(opx_octree_stats, inner_nodes))
INIT_TESTS(opx_urdf_options, opx_urdf_options_init, OPX_URDF_OPTIONS_INIT, "options",
           offsetof(opx_urdf_options, base_dir))
INIT_TESTS(opx_joint_info, opx_joint_info_init, OPX_JOINT_INFO_INIT, "info",
           offsetof(opx_joint_info, axis))
INIT_TESTS(opx_point_cloud_info, opx_point_cloud_info_init, OPX_POINT_CLOUD_INFO_INIT, "info",
           offsetof(opx_point_cloud_info, width))

/* The documented defaults, value by value (the macros could be wrong too). */
static void default_values_are_documented_ones(void **state) {
    (void)state;
    opx_octree_options o;
    assert_ok(opx_octree_options_init(&o, sizeof o));
    assert_true(o.resolution == 0.05 && o.prob_hit == 0.7 && o.prob_miss == 0.4);
    assert_true(o.clamp_min == 0.1192 && o.clamp_max == 0.971);
    assert_true(o.occupied_threshold == 0.5 && o.free_threshold == 0.5);

    opx_insert_options i;
    assert_ok(opx_insert_options_init(&i, sizeof i));
    assert_int_equal(i.mode, OPX_INSERT_RAYCAST);
    assert_true(i.max_range == -1.0);
    const opx_pose identity = OPX_POSE_IDENTITY;
    assert_memory_equal(&i.sensor_pose, &identity, sizeof identity);
    assert_true(identity.orientation[3] == 1.0);
}

/* Sizes and offsets fixed by the ABI (explicit padding, x86-64/aarch64). */
static void struct_layouts_are_fixed(void **state) {
    (void)state;
    assert_int_equal(sizeof(opx_pose), 56);
    assert_int_equal(sizeof(opx_octree_options), 64);
    assert_int_equal(offsetof(opx_octree_options, resolution), 8);
    assert_int_equal(sizeof(opx_insert_options), 160);
    assert_int_equal(offsetof(opx_insert_options, sensor_pose), 8);
    assert_int_equal(offsetof(opx_insert_options, max_threads), 72);
    assert_int_equal(offsetof(opx_insert_options, robot), 80);
    assert_int_equal(offsetof(opx_insert_options, robot_padding), 88);
    assert_int_equal(offsetof(opx_insert_options, clear_robot_volume), 96);
    assert_int_equal(offsetof(opx_insert_options, use_bounds), 104);
    assert_int_equal(offsetof(opx_insert_options, bounds_min), 112);
    assert_int_equal(offsetof(opx_insert_options, bounds_max), 136);
    assert_int_equal(sizeof(opx_insert_report), 88);
    assert_int_equal(offsetof(opx_insert_report, pixels_no_return), 56);
    assert_int_equal(offsetof(opx_insert_report, cells_cleared), 80);
    assert_int_equal(sizeof(opx_depth_image), 48);
    assert_int_equal(offsetof(opx_depth_image, data), 8);
    assert_int_equal(offsetof(opx_depth_image, depth_scale), 40);
    assert_int_equal(sizeof(opx_camera_intrinsics), 40);
    assert_int_equal(offsetof(opx_camera_intrinsics, fx), 8);
    assert_int_equal(sizeof(opx_cell_info), 56);
    assert_int_equal(offsetof(opx_cell_info, depth), 48);
    assert_int_equal(sizeof(opx_octree_stats), 160);
    assert_int_equal(offsetof(opx_octree_stats, leaves_with_extent), 152);
    assert_int_equal(sizeof(opx_leaf), 48);
    assert_int_equal(sizeof(opx_urdf_options), 40);
    assert_int_equal(offsetof(opx_urdf_options, package_dirs), 8);
    assert_int_equal(sizeof(opx_joint_info), 160);
    assert_int_equal(offsetof(opx_joint_info, axis), 24);
    assert_int_equal(offsetof(opx_joint_info, origin), 48);
    assert_int_equal(offsetof(opx_joint_info, lower), 112);
}

#define INIT_TEST_ENTRIES(FN)                                                                    \
    cmocka_unit_test(FN##_fills_the_defaults), cmocka_unit_test(FN##_writes_no_further_than_size), \
        cmocka_unit_test(FN##_accepts_a_larger_size), cmocka_unit_test(FN##_rejects_bad_arguments)

int main(void) {
    const struct CMUnitTest tests[] = {
        INIT_TEST_ENTRIES(opx_octree_options_init),
        INIT_TEST_ENTRIES(opx_insert_options_init),
        INIT_TEST_ENTRIES(opx_insert_report_init),
        INIT_TEST_ENTRIES(opx_depth_image_init),
        INIT_TEST_ENTRIES(opx_camera_intrinsics_init),
        INIT_TEST_ENTRIES(opx_cell_info_init),
        INIT_TEST_ENTRIES(opx_octree_stats_init),
        INIT_TEST_ENTRIES(opx_urdf_options_init),
        INIT_TEST_ENTRIES(opx_joint_info_init),
        INIT_TEST_ENTRIES(opx_point_cloud_info_init),
        cmocka_unit_test(default_values_are_documented_ones),
        cmocka_unit_test(struct_layouts_are_fixed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
