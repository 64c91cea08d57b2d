/*
 * Saving and loading .bt / .ot bytes, files and ROS message bodies: round
 * trips, buffer sizes, arguments, I/O errors.  The sample map (RES, two
 * rays) has 2 occupied cells (p 0.7) and 7 free cells (p 0.4).
 */
#include "opx_test.h"

#define NOT_NULL_SENTINEL ((opx_octree *)(uintptr_t)0x10)

static opx_octree *load_memory_ok(const byte_buffer *b, const opx_octree_options *options) {
    opx_octree *tree = NULL;
    assert_ok(opx_octree_load_memory(b->data, b->size, options, &tree));
    assert_non_null(tree);
    return tree;
}

/* Leaves equal but for the probability, which .bt does not keep: a loaded
 * leaf gets the clamping bound of its class. */
static void assert_bt_leaves(const opx_octree *loaded, const opx_octree *original) {
    size_t n = 0, m = 0;
    opx_leaf *got = all_leaves(loaded, OPX_MASK_ALL_KNOWN, &n);
    opx_leaf *want = all_leaves(original, OPX_MASK_ALL_KNOWN, &m);
    assert_int_equal(n, m);
    for (size_t i = 0; i < n; ++i) {
        assert_memory_equal(got[i].center, want[i].center, sizeof got[i].center);
        assert_true(got[i].size == want[i].size);
        assert_int_equal(got[i].depth, want[i].depth);
        assert_int_equal(got[i].cell_class, want[i].cell_class);
        assert_near(got[i].probability, want[i].cell_class == OPX_CELL_OCCUPIED ? 0.971 : 0.1192,
                    OPX_PROB_TOL);
    }
    free(got);
    free(want);
}

/* Same leaves, probabilities included (bit for bit), and same stats. */
static void assert_same_map(const opx_octree *a, const opx_octree *b) {
    map_snapshot sa = take_snapshot(a), sb = take_snapshot(b);
    assert_same_stats(&sa.stats, &sb.stats);
    assert_same_leaves(sa.leaves, sa.count, sb.leaves, sb.count);
    free(sa.leaves);
    free(sb.leaves);
}

static void memory_round_trip_ot_keeps_everything(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer ot = save_to_memory(tree, OPX_FORMAT_OT);
    assert_int_equal(memcmp(ot.data, "# Octomap OcTree file", 21), 0);
    opx_octree *loaded = load_memory_ok(&ot, NULL);
    assert_same_map(loaded, tree);
    /* AUTO reads the header. */
    assert_int_equal(stats_of(loaded).leaves_free, 7);
    opx_octree_destroy(loaded);
    opx_octree_destroy(tree);
    free(ot.data);
}

static void memory_round_trip_bt_keeps_classes(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer bt = save_to_memory(tree, OPX_FORMAT_BT);
    assert_int_equal(memcmp(bt.data, "# Octomap OcTree binary file", 28), 0);
    opx_octree *loaded = load_memory_ok(&bt, NULL);
    assert_bt_leaves(loaded, tree);
    /* AUTO for memory means BT. */
    byte_buffer automatic = save_to_memory(tree, OPX_FORMAT_AUTO);
    assert_int_equal(automatic.size, bt.size);
    assert_memory_equal(automatic.data, bt.data, bt.size);
    opx_octree_destroy(loaded);
    opx_octree_destroy(tree);
    free(bt.data);
    free(automatic.data);
}

/* The resolution comes from the file, the rest from the options. */
static void load_takes_resolution_from_file_and_thresholds_from_options(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer ot = save_to_memory(tree, OPX_FORMAT_OT);
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = 0.1;
    options.free_threshold = 0.3;
    options.occupied_threshold = 0.75;
    opx_octree *loaded = load_memory_ok(&ot, &options);
    opx_octree_options got = OPX_OCTREE_OPTIONS_INIT;
    assert_ok(opx_octree_get_options(loaded, &got));
    assert_true(got.resolution == RES);
    assert_true(got.free_threshold == 0.3 && got.occupied_threshold == 0.75);
    const opx_octree_stats s = stats_of(loaded);
    assert_int_equal(s.leaves_uncertain, 9); /* 0.4 and 0.7 both in [0.3, 0.75) */
    assert_int_equal(s.leaves_occupied + s.leaves_free, 0);
    opx_octree_destroy(loaded);
    opx_octree_destroy(tree);
    free(ot.data);
}

static void empty_map_round_trips(void **state) {
    (void)state;
    opx_octree *tree = new_tree(RES);
    const int32_t formats[2] = {OPX_FORMAT_BT, OPX_FORMAT_OT};
    for (int i = 0; i < 2; ++i) {
        byte_buffer b = save_to_memory(tree, formats[i]);
        opx_octree *loaded = load_memory_ok(&b, NULL);
        assert_same_map(loaded, tree);
        opx_octree_destroy(loaded);
        free(b.data);
    }
    opx_octree_destroy(tree);
}

static void message_bodies_load_like_files(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    const int32_t formats[2] = {OPX_FORMAT_BT, OPX_FORMAT_OT};
    for (int i = 0; i < 2; ++i) {
        byte_buffer file = save_to_memory(tree, formats[i]);
        const size_t body = body_offset(&file);
        opx_octree *from_file = load_memory_ok(&file, NULL);
        opx_octree *from_message = NULL;
        assert_ok(opx_octree_load_message(file.data + body, file.size - body,
                                          formats[i] == OPX_FORMAT_BT, RES, NULL, &from_message));
        assert_same_map(from_message, from_file);
        opx_octree_destroy(from_message);
        /* The message's resolution is used: the same cells, twice as big. */
        assert_ok(opx_octree_load_message(file.data + body, file.size - body,
                                          formats[i] == OPX_FORMAT_BT, 2 * RES, NULL,
                                          &from_message));
        const opx_octree_stats s = stats_of(from_message);
        assert_true(s.resolution == 2 * RES);
        assert_center(s.occupied_max, 2.5, 2.5, 0.5);
        opx_octree_destroy(from_message);
        opx_octree_destroy(from_file);
        free(file.data);
    }
    opx_octree_destroy(tree);
}

static void save_memory_reports_the_size_needed(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer bt = save_to_memory(tree, OPX_FORMAT_BT);
    unsigned char *buffer = malloc(bt.size + 8);
    memset(buffer, 0xAB, bt.size + 8);
    size_t needed = 0;
    expect_failure(OPX_ERROR_BUFFER_TOO_SMALL, "opx_octree_save_memory", NULL,
                   opx_octree_save_memory(tree, OPX_FORMAT_BT, buffer, bt.size - 1, &needed));
    assert_int_equal(needed, bt.size);
    for (size_t i = 0; i < bt.size + 8; ++i) assert_int_equal(buffer[i], 0xAB); /* nothing written */
    assert_ok(opx_octree_save_memory(tree, OPX_FORMAT_BT, buffer, bt.size + 8, &needed));
    assert_int_equal(needed, bt.size);
    assert_memory_equal(buffer, bt.data, bt.size);
    assert_int_equal(buffer[bt.size], 0xAB);
    free(buffer);
    free(bt.data);
    opx_octree_destroy(tree);
}

static void save_memory_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    const char *fn = "opx_octree_save_memory";
    unsigned char buffer[16];
    size_t size = 0;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "tree",
                   opx_octree_save_memory(NULL, OPX_FORMAT_BT, buffer, sizeof buffer, &size));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out_size",
                   opx_octree_save_memory(tree, OPX_FORMAT_BT, buffer, sizeof buffer, NULL));
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "buffer",
                   opx_octree_save_memory(tree, OPX_FORMAT_BT, NULL, 16, &size));
    const int32_t bad[] = {-1, 4, 99};
    for (size_t i = 0; i < 3; ++i)
        expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "format",
                       opx_octree_save_memory(tree, bad[i], buffer, sizeof buffer, &size));
    opx_octree_destroy(tree);
}

/* Loading fails with `expected` naming `argument`, and *out is NULL. */
static void expect_load_memory_fails(const void *data, size_t size,
                                     const opx_octree_options *options, opx_status expected,
                                     const char *argument) {
    opx_octree *out = NOT_NULL_SENTINEL;
    expect_failure(expected, "opx_octree_load_memory", argument,
                   opx_octree_load_memory(data, size, options, &out));
    assert_null(out);
}

static void load_memory_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer bt = save_to_memory(tree, OPX_FORMAT_BT);
    expect_load_memory_fails(NULL, bt.size, NULL, OPX_ERROR_INVALID_ARGUMENT, "data");
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_load_memory", "out",
                   opx_octree_load_memory(bt.data, bt.size, NULL, NULL));
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.struct_size = 0;
    expect_load_memory_fails(bt.data, bt.size, &options, OPX_ERROR_VERSION, "struct_size");
    options = (opx_octree_options)OPX_OCTREE_OPTIONS_INIT;
    options.prob_miss = 0.6;
    expect_load_memory_fails(bt.data, bt.size, &options, OPX_ERROR_INVALID_ARGUMENT, "prob_miss");
    options = (opx_octree_options)OPX_OCTREE_OPTIONS_INIT;
    options.clamp_max = NAN;
    expect_load_memory_fails(bt.data, bt.size, &options, OPX_ERROR_INVALID_ARGUMENT, "clamp_max");
    free(bt.data);
    opx_octree_destroy(tree);
}

static void load_message_rejects_bad_arguments(void **state) {
    (void)state;
    opx_octree *tree = new_sample_map();
    byte_buffer bt = save_to_memory(tree, OPX_FORMAT_BT);
    const size_t body = body_offset(&bt);
    const unsigned char *data = bt.data + body;
    const size_t size = bt.size - body;
    const char *fn = "opx_octree_load_message";
    opx_octree *out = NOT_NULL_SENTINEL;
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "data",
                   opx_octree_load_message(NULL, size, 1, RES, NULL, &out));
    assert_null(out);
    expect_failure(OPX_ERROR_INVALID_ARGUMENT, fn, "out",
                   opx_octree_load_message(data, size, 1, RES, NULL, NULL));
    /* A bad resolution: the header does not say whether it is an argument
     * or message data, so either code is accepted. */
    const double bad[] = {0.0, -RES, NAN, INFINITY};
    for (size_t i = 0; i < 4; ++i) {
        out = NOT_NULL_SENTINEL;
        const opx_status status = opx_octree_load_message(data, size, 1, bad[i], NULL, &out);
        assert_true(status == OPX_ERROR_INVALID_ARGUMENT || status == OPX_ERROR_CORRUPT);
        assert_non_null(strstr(opx_last_error(), fn));
        assert_non_null(strstr(opx_last_error(), "resolution"));
        assert_null(out);
    }
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.struct_size = 0;
    out = NOT_NULL_SENTINEL;
    expect_failure(OPX_ERROR_VERSION, fn, "struct_size",
                   opx_octree_load_message(data, size, 1, RES, &options, &out));
    assert_null(out);
    free(bt.data);
    opx_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(memory_round_trip_ot_keeps_everything),
        cmocka_unit_test(memory_round_trip_bt_keeps_classes),
        cmocka_unit_test(load_takes_resolution_from_file_and_thresholds_from_options),
        cmocka_unit_test(empty_map_round_trips),
        cmocka_unit_test(message_bodies_load_like_files),
        cmocka_unit_test(save_memory_reports_the_size_needed),
        cmocka_unit_test(save_memory_rejects_bad_arguments),
        cmocka_unit_test(load_memory_rejects_bad_arguments),
        cmocka_unit_test(load_message_rejects_bad_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
