/*
 * The opx_x_init functions of the link-set and query structs: defaults
 * equal to the OPX_X_INIT macros and to the documented values, a smaller
 * (older) size filled no further than that size, a larger size accepted,
 * and NULL or a size below 4 rejected.
 */
#include "opx_query_test.h"

#define SENTINEL 0xAB

static void assert_untouched(const void *p, size_t from, size_t to) {
    const unsigned char *bytes = p;
    for (size_t i = from; i < to; ++i)
        if (bytes[i] != SENTINEL) fail_msg("byte %zu was written (0x%02x)", i, bytes[i]);
}

/* Bytes [from, n) of a and b are equal, except the padding [gap, gap_end). */
static void assert_bytes_equal(const void *a, const void *b, size_t from, size_t n, size_t gap,
                               size_t gap_end) {
    const unsigned char *x = a, *y = b;
    for (size_t i = from; i < n; ++i) {
        if (i >= gap && i < gap_end) continue;
        if (x[i] != y[i]) fail_msg("byte %zu is 0x%02x, expected 0x%02x", i, x[i], y[i]);
    }
}

/* T, its init function FN and macro INIT, the name ARG of its pointer in
 * the header, an older size PARTIAL, and padding bytes [GAP, GAP_END) that
 * hold no field (GAP == GAP_END: none). */
#define INIT_TESTS(T, FN, INIT, ARG, PARTIAL, GAP, GAP_END)                                      \
    static void FN##_fills_the_defaults(void **state) {                                          \
        (void)state;                                                                             \
        const T expected = INIT;                                                                 \
        T value;                                                                                 \
        memset(&value, SENTINEL, sizeof value);                                                  \
        assert_ok(FN(&value, sizeof value));                                                     \
        assert_int_equal(value.struct_size, sizeof(T));                                          \
        assert_bytes_equal(&value, &expected, 0, sizeof value, GAP, GAP_END);                    \
    }                                                                                            \
    static void FN##_writes_no_further_than_size(void **state) {                                 \
        (void)state;                                                                             \
        const T expected = INIT;                                                                 \
        T value;                                                                                 \
        memset(&value, SENTINEL, sizeof value);                                                  \
        assert_ok(FN(&value, PARTIAL));                                                          \
        assert_int_equal(value.struct_size, PARTIAL);                                            \
        assert_bytes_equal(&value, &expected, sizeof(uint32_t), PARTIAL, GAP, GAP_END);          \
        assert_untouched(&value, PARTIAL, sizeof value);                                         \
    }                                                                                            \
    static void FN##_accepts_a_larger_size(void **state) {                                       \
        (void)state;                                                                             \
        const T expected = INIT;                                                                 \
        struct {                                                                                 \
            T value;                                                                             \
            unsigned char newer_fields[32];                                                      \
        } bigger;                                                                                \
        memset(&bigger, SENTINEL, sizeof bigger);                                                \
        assert_ok(FN(&bigger.value, sizeof bigger));                                             \
        assert_int_equal(bigger.value.struct_size, sizeof(T));                                   \
        assert_bytes_equal(&bigger.value, &expected, sizeof(uint32_t), sizeof(T), GAP, GAP_END); \
    }                                                                                            \
    static void FN##_rejects_bad_arguments(void **state) {                                       \
        (void)state;                                                                             \
        T value;                                                                                 \
        memset(&value, SENTINEL, sizeof value);                                                  \
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, #FN, ARG, FN(NULL, sizeof value));            \
        expect_failure(OPX_ERROR_VERSION, #FN, "size", FN(&value, 0));                           \
        assert_untouched(&value, 0, sizeof value);                                               \
        expect_failure(OPX_ERROR_VERSION, #FN, "size", FN(&value, 3));                           \
        assert_untouched(&value, 0, sizeof value);                                               \
    }

INIT_TESTS(opx_shape, opx_shape_init, OPX_SHAPE_INIT, "shape", offsetof(opx_shape, radius), 0, 0)
INIT_TESTS(opx_query_options, opx_query_options_init, OPX_QUERY_OPTIONS_INIT, "options",
           sizeof(uint32_t), 0, 0)
INIT_TESTS(opx_collision_request, opx_collision_request_init, OPX_COLLISION_REQUEST_INIT,
           "request", offsetof(opx_collision_request, compute_cost), 0, 0)
INIT_TESTS(opx_collision_result, opx_collision_result_init, OPX_COLLISION_RESULT_INIT, "result",
           offsetof(opx_collision_result, narrow_tests), 0, 0)
/* opx_contact has 4 bytes of implicit padding after cell_class. */
INIT_TESTS(opx_contact, opx_contact_init, OPX_CONTACT_INIT, "contact",
           offsetof(opx_contact, depth), offsetof(opx_contact, cell_class) + sizeof(int32_t),
           offsetof(opx_contact, cell_center))
INIT_TESTS(opx_cost_box, opx_cost_box_init, OPX_COST_BOX_INIT, "box",
           offsetof(opx_cost_box, probability), 0, 0)
INIT_TESTS(opx_distance_request, opx_distance_request_init, OPX_DISTANCE_REQUEST_INIT, "request",
           offsetof(opx_distance_request, cutoff), 0, 0)
INIT_TESTS(opx_distance_result, opx_distance_result_init, OPX_DISTANCE_RESULT_INIT, "result",
           offsetof(opx_distance_result, point_on_cell), 0, 0)
INIT_TESTS(opx_path_request, opx_path_request_init, OPX_PATH_REQUEST_INIT, "request",
           offsetof(opx_path_request, unknown_probability), 0, 0)
INIT_TESTS(opx_path_result, opx_path_result_init, OPX_PATH_RESULT_INIT, "result",
           offsetof(opx_path_result, total_cost), 0, 0)
INIT_TESTS(opx_batch_request, opx_batch_request_init, OPX_BATCH_REQUEST_INIT, "request",
           offsetof(opx_batch_request, compute_distance), 0, 0)
INIT_TESTS(opx_motion_request, opx_motion_request_init, OPX_MOTION_REQUEST_INIT, "request",
           offsetof(opx_motion_request, self_collision), 0, 0)
INIT_TESTS(opx_motion_result, opx_motion_result_init, OPX_MOTION_RESULT_INIT, "result",
           offsetof(opx_motion_result, steps), 0, 0)

/* The documented defaults, value by value (the macros could be wrong too). */
static void default_values_are_documented_ones(void **state) {
    (void)state;
    opx_shape shape;
    assert_ok(opx_shape_init(&shape, sizeof shape));
    const opx_pose identity = OPX_POSE_IDENTITY;
    assert_memory_equal(&shape.pose, &identity, sizeof identity);
    assert_true(identity.orientation[3] == 1.0);
    assert_null(shape.vertices);
    assert_null(shape.indices);

    opx_query_options options;
    assert_ok(opx_query_options_init(&options, sizeof options));
    assert_int_equal(options.engine, OPX_ENGINE_DIRECT);

    opx_collision_request c;
    assert_ok(opx_collision_request_init(&c, sizeof c));
    assert_int_equal(c.unknown_policy, OPX_UNKNOWN_FREE);
    assert_true(c.occupancy_threshold == 0.0);
    assert_int_equal(c.max_contacts, 1);
    assert_int_equal(c.compute_cost, 0);
    assert_int_equal(c.max_cost_boxes, 16);
    assert_true(c.unknown_probability == 0.5);
    assert_int_equal(c.compute_penetration, 0);

    opx_distance_request d;
    assert_ok(opx_distance_request_init(&d, sizeof d));
    assert_int_equal(d.unknown_policy, OPX_UNKNOWN_FREE);
    assert_true(d.abs_err == 0.0 && d.rel_err == 0.0 && d.cutoff == 0.0);
    assert_int_equal(d.per_link + d.signed_distance, 0);

    opx_path_request p;
    assert_ok(opx_path_request_init(&p, sizeof p));
    assert_int_equal(p.max_cost_boxes, 16);
    assert_true(p.unknown_probability == 0.5);
    assert_int_equal(p.compute_distance + p.compute_cost, 0);

    opx_path_result r;
    assert_ok(opx_path_result_init(&r, sizeof r));
    assert_int_equal(r.first_colliding_waypoint, -1);
    assert_int_equal(r.min_distance_waypoint, -1);

    opx_batch_request b;
    assert_ok(opx_batch_request_init(&b, sizeof b));
    assert_int_equal(b.max_threads, 1);
    assert_int_equal(b.self_collision + b.compute_distance, 0);
    assert_true(b.distance_cutoff == 0.0);
    assert_int_equal(b.joint_order, OPX_JOINTS_BY_COUNT);

    opx_motion_request m;
    assert_ok(opx_motion_request_init(&m, sizeof m));
    assert_true(m.resolution == 0.01);
    assert_int_equal(m.max_threads, 1);
    assert_int_equal(m.max_cost_boxes, 16);
    assert_int_equal(m.self_collision + m.compute_cost, 0);
    assert_int_equal(m.joint_order, OPX_JOINTS_BY_COUNT);
    assert_int_equal(m.check, OPX_MOTION_SAMPLED);
    assert_true(m.tolerance == 1e-3);

    opx_motion_result mr;
    assert_ok(opx_motion_result_init(&mr, sizeof mr));
    assert_true(mr.first_collision_fraction == -1.0);
}

/* The batch structs' layouts: fixed-width fields, no implicit padding. */
static void batch_struct_layouts_are_fixed(void **state) {
    (void)state;
    assert_int_equal(sizeof(opx_batch_request), 48);
    assert_int_equal(offsetof(opx_batch_request, distance_cutoff), 24);
    assert_int_equal(offsetof(opx_batch_request, max_threads), 32);
    assert_int_equal(offsetof(opx_batch_request, obstacle_geometry), 36);
    assert_int_equal(offsetof(opx_batch_request, joint_order), 40);
    assert_int_equal(sizeof(opx_motion_request), 128);
    assert_int_equal(offsetof(opx_motion_request, check), 112);
    assert_int_equal(offsetof(opx_motion_request, tolerance), 120);
    assert_int_equal(offsetof(opx_motion_request, obstacle_geometry), 96);
    assert_int_equal(offsetof(opx_motion_request, joint_order), 104);
    assert_int_equal(offsetof(opx_motion_request, resolution), 16);
    assert_int_equal(offsetof(opx_motion_request, max_threads), 36);
    assert_int_equal(offsetof(opx_motion_request, region_max), 72);
    assert_int_equal(sizeof(opx_motion_result), 56);
    assert_int_equal(offsetof(opx_motion_result, cost_boxes_found), 48);
}

#define INIT_TEST_ENTRIES(FN)                                                                    \
    cmocka_unit_test(FN##_fills_the_defaults), cmocka_unit_test(FN##_writes_no_further_than_size), \
        cmocka_unit_test(FN##_accepts_a_larger_size), cmocka_unit_test(FN##_rejects_bad_arguments)

int main(void) {
    const struct CMUnitTest tests[] = {
        INIT_TEST_ENTRIES(opx_shape_init),
        INIT_TEST_ENTRIES(opx_query_options_init),
        INIT_TEST_ENTRIES(opx_collision_request_init),
        INIT_TEST_ENTRIES(opx_collision_result_init),
        INIT_TEST_ENTRIES(opx_contact_init),
        INIT_TEST_ENTRIES(opx_cost_box_init),
        INIT_TEST_ENTRIES(opx_distance_request_init),
        INIT_TEST_ENTRIES(opx_distance_result_init),
        INIT_TEST_ENTRIES(opx_path_request_init),
        INIT_TEST_ENTRIES(opx_path_result_init),
        INIT_TEST_ENTRIES(opx_batch_request_init),
        INIT_TEST_ENTRIES(opx_motion_request_init),
        INIT_TEST_ENTRIES(opx_motion_result_init),
        cmocka_unit_test(default_values_are_documented_ones),
        cmocka_unit_test(batch_struct_layouts_are_fixed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
