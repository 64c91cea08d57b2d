/* opx_octree_create, _destroy, _clear and _get_options: options checked
 * field by field, *out NULL on failure, options kept. */
#include "opx_test.h"

/* A pointer that is not NULL and never dereferenced: proves *out is reset. */
#define NOT_NULL_SENTINEL ((opx_octree *)(uintptr_t)0x10)

/* Creating with these options fails with `expected`, naming `field`, and
 * sets *out to NULL. */
static void expect_create_fails(const opx_octree_options *options, opx_status expected,
                                const char *field) {
    opx_octree *tree = NOT_NULL_SENTINEL;
    expect_failure(expected, "opx_octree_create", field, opx_octree_create(options, &tree));
    assert_null(tree);
}

/* Defaults with one field changed. */
static opx_octree_options with_field(size_t offset, double value) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    memcpy((char *)&options + offset, &value, sizeof value);
    return options;
}

#define BAD_FIELD(field, value)                                                            \
    do {                                                                                   \
        const opx_octree_options o_ = with_field(offsetof(opx_octree_options, field), value); \
        expect_create_fails(&o_, OPX_ERROR_INVALID_ARGUMENT, #field);                     \
    } while (0)

static void create_with_null_options_uses_defaults(void **state) {
    (void)state;
    opx_octree *tree = NULL;
    assert_ok(opx_octree_create(NULL, &tree));
    assert_non_null(tree);
    opx_octree_options got = OPX_OCTREE_OPTIONS_INIT;
    assert_ok(opx_octree_get_options(tree, &got));
    const opx_octree_options defaults = OPX_OCTREE_OPTIONS_INIT;
    assert_memory_equal(&got, &defaults, sizeof got);
    opx_octree_destroy(tree);
}

static void get_options_returns_the_create_options(void **state) {
    (void)state;
    const opx_octree_options options = {sizeof(opx_octree_options), 0, 0.2, 0.65, 0.45, 0.12,
                                        0.97, 0.6, 0.3};
    opx_octree *tree = new_tree_with(&options);
    opx_octree_options got = OPX_OCTREE_OPTIONS_INIT;
    assert_ok(opx_octree_get_options(tree, &got));
    assert_memory_equal(&got, &options, sizeof got);
    opx_octree_destroy(tree);
}

static void create_rejects_null_out(void **state) {
    (void)state;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_create", "out",
                   opx_octree_create(NULL, NULL));
}

static void create_rejects_struct_size_zero(void **state) {
    (void)state;
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.struct_size = 0;
    expect_create_fails(&options, OPX_ERROR_VERSION, "struct_size");
}

static void create_rejects_bad_resolution(void **state) {
    (void)state;
    BAD_FIELD(resolution, 0.0);
    BAD_FIELD(resolution, -0.05);
    BAD_FIELD(resolution, NAN);
    BAD_FIELD(resolution, INFINITY);
    BAD_FIELD(resolution, -INFINITY);
    BAD_FIELD(resolution, 5e-324); /* denormal: 1/resolution is infinite */
    BAD_FIELD(resolution, 0.99e-6);
    BAD_FIELD(resolution, 1.01e6);
    BAD_FIELD(resolution, 1e300);
}

static void create_accepts_the_resolution_range_ends(void **state) {
    (void)state;
    const double ends[2] = {1e-6, 1e6};
    for (int i = 0; i < 2; ++i) {
        opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
        options.resolution = ends[i];
        opx_octree *tree = NULL;
        assert_ok(opx_octree_create(&options, &tree));
        const double probe[3] = {0.0, 0.0, 0.0};
        opx_cell_info cell = OPX_CELL_INFO_INIT;
        assert_ok(opx_octree_classify(tree, probe, &cell));
        opx_octree_destroy(tree);
    }
}

static void create_rejects_non_finite_probabilities(void **state) {
    (void)state;
    BAD_FIELD(prob_hit, NAN);
    BAD_FIELD(prob_miss, NAN);
    BAD_FIELD(clamp_min, NAN);
    BAD_FIELD(clamp_max, INFINITY);
    BAD_FIELD(occupied_threshold, NAN);
    BAD_FIELD(free_threshold, -INFINITY);
}

static void create_rejects_probabilities_outside_0_1(void **state) {
    (void)state;
    BAD_FIELD(prob_hit, 1.0);
    BAD_FIELD(prob_hit, 1.5);
    BAD_FIELD(prob_miss, 0.0);
    BAD_FIELD(prob_miss, -0.1);
    BAD_FIELD(clamp_min, 0.0);
    BAD_FIELD(clamp_max, 1.0);
    BAD_FIELD(occupied_threshold, 1.0);
    BAD_FIELD(free_threshold, 0.0);
}

static void create_rejects_bad_probability_combinations(void **state) {
    (void)state;
    BAD_FIELD(prob_hit, 0.5);  /* a hit must raise occupancy */
    BAD_FIELD(prob_hit, 0.3);
    BAD_FIELD(prob_miss, 0.5); /* a miss must lower it */
    BAD_FIELD(prob_miss, 0.8);
    BAD_FIELD(clamp_min, 0.971); /* clamp_min == clamp_max */
    BAD_FIELD(clamp_min, 0.99);
    BAD_FIELD(free_threshold, 0.6); /* above occupied_threshold 0.5 */
    BAD_FIELD(occupied_threshold, 0.4); /* below free_threshold 0.5 */
}

static void create_accepts_edge_combinations(void **state) {
    (void)state;
    /* free_threshold == occupied_threshold is allowed ("<="). */
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.free_threshold = options.occupied_threshold = 0.7;
    opx_octree_destroy(new_tree_with(&options));
    options.free_threshold = 0.01;
    options.occupied_threshold = 0.99;
    opx_octree_destroy(new_tree_with(&options));
}

/* An older caller's struct: the fields it does not know take defaults,
 * whatever lies in memory after its struct_size. */
static void create_reads_no_further_than_struct_size(void **state) {
    (void)state;
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = 0.1;
    options.free_threshold = 0.9; /* invalid if read: above occupied 0.5 */
    options.struct_size = (uint32_t)offsetof(opx_octree_options, free_threshold);
    opx_octree *tree = new_tree_with(&options);
    opx_octree_options got = OPX_OCTREE_OPTIONS_INIT;
    assert_ok(opx_octree_get_options(tree, &got));
    assert_true(got.resolution == 0.1);
    assert_true(got.free_threshold == 0.5);
    opx_octree_destroy(tree);
}

static void get_options_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_tree(0.1);
    opx_octree_options got = OPX_OCTREE_OPTIONS_INIT;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_get_options", "tree",
                   opx_octree_get_options(NULL, &got));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_get_options", "out",
                   opx_octree_get_options(tree, NULL));
    got.struct_size = 0;
    expect_failure(OPX_ERROR_VERSION, "opx_octree_get_options", "struct_size",
                   opx_octree_get_options(tree, &got));
    opx_octree_destroy(tree);
}

/* A smaller out struct is written no further than its struct_size. */
static void get_options_writes_no_further_than_struct_size(void **state) {
    (void)state;
    opx_octree *tree = new_tree(0.1);
    opx_octree_options got;
    memset(&got, 0xAB, sizeof got);
    got.struct_size = (uint32_t)offsetof(opx_octree_options, prob_hit);
    assert_ok(opx_octree_get_options(tree, &got));
    assert_int_equal(got.struct_size, offsetof(opx_octree_options, prob_hit));
    assert_true(got.resolution == 0.1);
    const unsigned char *bytes = (const unsigned char *)&got;
    for (size_t i = offsetof(opx_octree_options, prob_hit); i < sizeof got; ++i)
        assert_int_equal(bytes[i], 0xAB);
    opx_octree_destroy(tree);
}

static void clear_removes_every_cell_and_keeps_options(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    assert_int_equal(stats_of(tree).leaves_occupied, 2);
    assert_ok(opx_octree_clear(tree));
    const opx_octree_stats stats = stats_of(tree);
    assert_int_equal(stats.leaves_occupied + stats.leaves_free + stats.leaves_uncertain, 0);
    assert_int_equal(stats.inner_nodes, 0);
    assert_int_equal(stats.has_occupied, 0);
    assert_true(stats.resolution == RES);
    assert_int_equal(classify_at(tree, 1.125, C0, C0).cell_class, OPX_CELL_UNKNOWN);
    /* Still usable after clearing. */
    insert_one_ray(tree, 1.0, 0.0, 0.0);
    assert_int_equal(stats_of(tree).leaves_occupied, 1);
    opx_octree_destroy(tree);
}

static void clear_rejects_null(void **state) {
    (void)state;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_clear", "tree", opx_octree_clear(NULL));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(create_with_null_options_uses_defaults),
        cmocka_unit_test(get_options_returns_the_create_options),
        cmocka_unit_test(create_rejects_null_out),
        cmocka_unit_test(create_rejects_struct_size_zero),
        cmocka_unit_test(create_rejects_bad_resolution),
        cmocka_unit_test(create_accepts_the_resolution_range_ends),
        cmocka_unit_test(create_rejects_non_finite_probabilities),
        cmocka_unit_test(create_rejects_probabilities_outside_0_1),
        cmocka_unit_test(create_rejects_bad_probability_combinations),
        cmocka_unit_test(create_accepts_edge_combinations),
        cmocka_unit_test(create_reads_no_further_than_struct_size),
        cmocka_unit_test(get_options_rejects_bad_arguments),
        cmocka_unit_test(get_options_writes_no_further_than_struct_size),
        cmocka_unit_test(clear_removes_every_cell_and_keeps_options),
        cmocka_unit_test(clear_rejects_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
