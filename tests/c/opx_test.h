/*
 * Helpers shared by the CMocka tests of the C ABI: failure checks that look
 * at the status, the message and the map, tolerant comparisons, small maps
 * built by hand, and byte buffers for the file formats.
 *
 * Every helper is `static inline` so each test file includes what it needs
 * without unused-function warnings.
 */
#ifndef OPX_TEST_H
#define OPX_TEST_H

/* cmocka.h needs these before it. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <octoprox/octoprox.h>

/* OctoMap stores log-odds as float: probabilities match to ~1e-7. */
#define OPX_PROB_TOL 1e-6
/* Cell geometry is computed in double from integer keys. */
#define OPX_GEOM_TOL 1e-9

/* The resolution of the hand-computed maps: a power of two, so cell
 * boundaries and centres are exact in float and double. */
#define RES 0.25
/* A cell centre near the origin, where most test sensors sit. */
#define C0 0.125

static inline double log_odds(double p) { return log(p / (1.0 - p)); }
static inline double probability(double l) { return 1.0 / (1.0 + exp(-l)); }

/* ---- Comparisons ------------------------------------------------------- */

#define assert_near(actual, expected, tol) \
    opx_assert_near((actual), (expected), (tol), #actual, __FILE__, __LINE__)

static inline void opx_assert_near(double actual, double expected, double tol, const char *what,
                                   const char *file, int line) {
    if (!(fabs(actual - expected) <= tol))
        fail_msg("%s:%d: %s is %.12g, expected %.12g (+-%g)", file, line, what, actual, expected,
                 tol);
}

#define assert_center(c, x, y, z)                  \
    do {                                           \
        assert_near((c)[0], (x), OPX_GEOM_TOL);    \
        assert_near((c)[1], (y), OPX_GEOM_TOL);    \
        assert_near((c)[2], (z), OPX_GEOM_TOL);    \
    } while (0)

#define assert_status(call, expected) \
    opx_assert_status((call), (expected), #call, __FILE__, __LINE__)

static inline void opx_assert_status(opx_status actual, opx_status expected, const char *call,
                                     const char *file, int line) {
    if (actual != expected)
        fail_msg("%s:%d: %s returned %s (%d), expected %s (%d); last error: \"%s\"", file, line, call,
                 opx_status_name(actual), (int)actual, opx_status_name(expected), (int)expected,
                 opx_last_error());
}

#define assert_ok(call) assert_status((call), OPX_OK)

/* ---- Failures ---------------------------------------------------------- */

/* Makes the thread's last error name a function other than `function`, so
 * the check after the call under test proves the message is fresh. */
static inline void opx_prime_last_error(const char *function) {
    if (strcmp(function, "opx_octree_clear") != 0) {
        assert_int_equal(opx_octree_clear(NULL), OPX_ERROR_INVALID_ARGUMENT);
        assert_non_null(strstr(opx_last_error(), "opx_octree_clear"));
    } else {
        assert_int_equal(opx_octree_get_stats(NULL, NULL), OPX_ERROR_INVALID_ARGUMENT);
        assert_non_null(strstr(opx_last_error(), "opx_octree_get_stats"));
    }
}

static inline void opx_check_failure(opx_status actual, opx_status expected, const char *function,
                                     const char *argument, const char *call, const char *file,
                                     int line) {
    const char *message = opx_last_error();
    opx_assert_status(actual, expected, call, file, line);
    if (strstr(message, function) == NULL)
        fail_msg("%s:%d: %s: last error \"%s\" does not name the function %s", file, line, call,
                 message, function);
    if (argument != NULL && strstr(message, argument) == NULL)
        fail_msg("%s:%d: %s: last error \"%s\" does not name the argument \"%s\"", file, line,
                 call, message, argument);
}

/* Runs `call` and checks its status and that opx_last_error() names the
 * function and the argument (argument NULL: not checked). */
#define expect_failure(expected, function, argument, call)                                    \
    do {                                                                                      \
        opx_prime_last_error(function);                                                       \
        const opx_status status_ = (call);                                                    \
        opx_check_failure(status_, (expected), (function), (argument), #call, __FILE__,       \
                          __LINE__);                                                          \
    } while (0)

/* ---- Snapshots: proof that a failed call left the map alone ------------ */

typedef struct map_snapshot {
    opx_octree_stats stats;
    opx_leaf *leaves;
    size_t count;
} map_snapshot;

static inline opx_leaf *all_leaves(const opx_octree *tree, uint32_t mask, size_t *out_count) {
    size_t count = 0;
    opx_status status = opx_octree_get_leaves(tree, mask, NULL, 0, &count);
    assert_true(status == OPX_OK || status == OPX_ERROR_BUFFER_TOO_SMALL);
    opx_leaf *leaves = calloc(count + 1, sizeof *leaves);
    assert_non_null(leaves);
    size_t written = 0;
    assert_ok(opx_octree_get_leaves(tree, mask, leaves, count, &written));
    assert_int_equal(written, count);
    *out_count = count;
    return leaves;
}

static inline opx_octree_stats stats_of(const opx_octree *tree) {
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    assert_ok(opx_octree_get_stats(tree, &stats));
    return stats;
}

static inline map_snapshot take_snapshot(const opx_octree *tree) {
    map_snapshot s;
    s.stats = stats_of(tree);
    s.leaves = all_leaves(tree, OPX_MASK_ALL_KNOWN, &s.count);
    return s;
}

static inline void assert_same_stats(const opx_octree_stats *a, const opx_octree_stats *b) {
    assert_int_equal(a->has_occupied, b->has_occupied);
    assert_true(a->resolution == b->resolution);
    assert_int_equal(a->leaves_occupied, b->leaves_occupied);
    assert_int_equal(a->leaves_uncertain, b->leaves_uncertain);
    assert_int_equal(a->leaves_free, b->leaves_free);
    assert_int_equal(a->inner_nodes, b->inner_nodes);
    assert_memory_equal(a->occupied_min, b->occupied_min, sizeof a->occupied_min);
    assert_memory_equal(a->occupied_max, b->occupied_max, sizeof a->occupied_max);
    assert_memory_equal(a->known_min, b->known_min, sizeof a->known_min);
    assert_memory_equal(a->known_max, b->known_max, sizeof a->known_max);
}

static inline void assert_same_leaves(const opx_leaf *a, size_t count_a, const opx_leaf *b,
                                      size_t count_b) {
    assert_int_equal(count_a, count_b);
    if (count_a > 0) assert_memory_equal(a, b, count_a * sizeof *a);
}

/* Both maps hold the same known leaves, bit for bit. */
static inline void assert_same_known_leaves(const opx_octree *got, const opx_octree *want) {
    size_t n = 0, m = 0;
    opx_leaf *got_leaves = all_leaves(got, OPX_MASK_ALL_KNOWN, &n);
    opx_leaf *want_leaves = all_leaves(want, OPX_MASK_ALL_KNOWN, &m);
    assert_same_leaves(got_leaves, n, want_leaves, m);
    free(got_leaves);
    free(want_leaves);
}

/* The map has the same stats (memory included) and leaves as before. */
static inline void assert_unchanged(const opx_octree *tree, map_snapshot *before) {
    map_snapshot now = take_snapshot(tree);
    assert_same_stats(&now.stats, &before->stats);
    assert_int_equal(now.stats.memory_bytes, before->stats.memory_bytes);
    assert_same_leaves(now.leaves, now.count, before->leaves, before->count);
    free(now.leaves);
    free(before->leaves);
    before->leaves = NULL;
}

/* ---- Building maps ----------------------------------------------------- */

static inline opx_octree *new_tree_with(const opx_octree_options *options) {
    opx_octree *tree = NULL;
    assert_ok(opx_octree_create(options, &tree));
    assert_non_null(tree);
    return tree;
}

static inline opx_octree *new_tree(double resolution) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    return new_tree_with(&options);
}

/* Insert options with the sensor at (x, y, z), identity orientation. */
static inline opx_insert_options sensor_at(double x, double y, double z, int32_t mode) {
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    options.mode = mode;
    options.sensor_pose.position[0] = x;
    options.sensor_pose.position[1] = y;
    options.sensor_pose.position[2] = z;
    return options;
}

/* Inserts packed float64 points (sensor frame); returns the report. */
static inline opx_insert_report insert_f64(opx_octree *tree, const double *xyz, size_t count,
                                           const opx_insert_options *options) {
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    assert_ok(opx_octree_insert_points(tree, xyz, count, 0, OPX_SCALAR_FLOAT64, options, &report));
    return report;
}

/* One ray-cast point (sensor frame) from a sensor at the centre of the
 * cell [0, RES)^3. */
static inline opx_insert_report insert_one_ray(opx_octree *tree, double x, double y, double z) {
    const double xyz[3] = {x, y, z};
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    return insert_f64(tree, xyz, 1, &options);
}

/* A small map at RES: two rays from (C0, C0, C0), to (1, 0, 0) and (0, 1, 0)
 * in the sensor frame: 2 occupied cells, 7 free cells. */
static inline opx_octree *new_sample_map(void) {
    opx_octree *tree = new_tree(RES);
    const double xyz[6] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0};
    const opx_insert_options options = sensor_at(C0, C0, C0, OPX_INSERT_RAYCAST);
    opx_insert_report report = insert_f64(tree, xyz, 2, &options);
    assert_int_equal(report.cells_hit, 2);
    assert_int_equal(report.cells_missed, 7);
    return tree;
}

static inline opx_cell_info classify_at(const opx_octree *tree, double x, double y, double z) {
    const double point[3] = {x, y, z};
    opx_cell_info info = OPX_CELL_INFO_INIT;
    assert_ok(opx_octree_classify(tree, point, &info));
    return info;
}

/* ---- Byte buffers of saved maps ---------------------------------------- */

typedef struct byte_buffer {
    unsigned char *data;
    size_t size;
} byte_buffer;

/* The bytes of the file at path (the test fails when it cannot be read). */
static inline byte_buffer read_whole_file(const char *path) {
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    byte_buffer b = {NULL, 0};
    unsigned char chunk[4096];
    size_t n;
    while ((n = fread(chunk, 1, sizeof chunk, f)) > 0) {
        b.data = realloc(b.data, b.size + n);
        assert_non_null(b.data);
        memcpy(b.data + b.size, chunk, n);
        b.size += n;
    }
    fclose(f);
    return b;
}

static inline byte_buffer save_to_memory(const opx_octree *tree, int32_t format) {
    byte_buffer b = {NULL, 0};
    assert_status(opx_octree_save_memory(tree, format, NULL, 0, &b.size),
                  OPX_ERROR_BUFFER_TOO_SMALL);
    assert_true(b.size > 0);
    b.data = malloc(b.size);
    assert_non_null(b.data);
    size_t written = 0;
    assert_ok(opx_octree_save_memory(tree, format, b.data, b.size, &written));
    assert_int_equal(written, b.size);
    return b;
}

/* Offset of the first byte after the header line "data". */
static inline size_t body_offset(const byte_buffer *b) {
    static const char marker[] = "\ndata\n";
    const size_t n = sizeof marker - 1;
    for (size_t i = 0; i + n <= b->size; ++i)
        if (memcmp(b->data + i, marker, n) == 0) return i + n;
    fail_msg("no \"data\" line in the saved map");
    return 0;
}

/* A copy of b with the header line starting with `key` replaced by `line`
 * (without its newline). */
static inline byte_buffer replace_header_line(const byte_buffer *b, const char *key,
                                              const char *line) {
    const size_t body = body_offset(b);
    const size_t key_len = strlen(key);
    for (size_t i = 0; i < body; ++i) {
        if ((i == 0 || b->data[i - 1] == '\n') && memcmp(b->data + i, key, key_len) == 0) {
            size_t end = i;
            while (b->data[end] != '\n') ++end;
            const size_t line_len = strlen(line);
            byte_buffer out = {malloc(b->size - (end - i) + line_len), 0};
            assert_non_null(out.data);
            memcpy(out.data, b->data, i);
            memcpy(out.data + i, line, line_len);
            memcpy(out.data + i + line_len, b->data + end, b->size - end);
            out.size = b->size - (end - i) + line_len;
            return out;
        }
    }
    fail_msg("no header line \"%s\"", key);
    return *b;
}

#endif /* OPX_TEST_H */
