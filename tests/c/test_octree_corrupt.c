/*
 * Corrupt and truncated .bt / .ot bytes: OPX_ERROR_CORRUPT, *out NULL, no
 * crash (run under ASan too).  The inputs are made from a saved sample map:
 * truncated at every length, bodies overwritten, header lines replaced,
 * bits flipped, trees deeper than 16 levels.
 */
#include "opx_test.h"

#define NOT_NULL_SENTINEL ((opx_octree *)(uintptr_t)0x10)

static const int32_t FORMATS[2] = {OPX_FORMAT_BT, OPX_FORMAT_OT};

static byte_buffer sample_bytes(int32_t format) {
    opx_octree *tree = new_sample_map();
    byte_buffer b = save_to_memory(tree, format);
    opx_octree_destroy(tree);
    return b;
}

/* Loads data; returns 1 when the status is `expected`, the message names
 * the function and *out is NULL, else prints why and returns 0. */
static int load_gives(const void *data, size_t size, opx_status expected, const char *what) {
    opx_octree *out = NOT_NULL_SENTINEL;
    const opx_status status = opx_octree_load_memory(data, size, NULL, &out);
    if (status == OPX_OK && out != NULL && out != NOT_NULL_SENTINEL) opx_octree_destroy(out);
    if (status != expected) {
        print_error("%s (%zu bytes): %s, expected %s%s%s\n", what, size, opx_status_name(status),
                    opx_status_name(expected), status == OPX_OK ? "" : "; last error: ",
                    status == OPX_OK ? "" : opx_last_error());
        return 0;
    }
    if (status != OPX_OK && (strstr(opx_last_error(), "opx_octree_load_memory") == NULL ||
                             out != NULL)) {
        print_error("%s: message \"%s\" or *out %p wrong\n", what, opx_last_error(), (void *)out);
        return 0;
    }
    return 1;
}

static void expect_load_status(const void *data, size_t size, opx_status expected,
                               const char *what) {
    if (!load_gives(data, size, expected, what)) fail();
}

static void expect_corrupt(const byte_buffer *b, const char *what) {
    expect_load_status(b->data, b->size, OPX_ERROR_CORRUPT, what);
}

/* Every strict prefix, from 0 bytes to all but the last one; all failing
 * lengths are listed before the test fails. */
static void every_truncation_is_corrupt(void **state) {
    (void)state;
    int failures = 0;
    for (int f = 0; f < 2; ++f) {
        byte_buffer b = sample_bytes(FORMATS[f]);
        for (size_t size = 0; size < b.size; ++size) {
            char what[64];
            snprintf(what, sizeof what, "format %d cut at %zu", (int)FORMATS[f], size);
            /* A copy of exactly `size` bytes, so ASan sees any over-read. */
            unsigned char *copy = malloc(size + 1);
            memcpy(copy, b.data, size);
            failures += !load_gives(copy, size, OPX_ERROR_CORRUPT, what);
            free(copy);
        }
        free(b.data);
    }
    assert_int_equal(failures, 0);
}

static void body_filled_with(const byte_buffer *b, unsigned char value, const char *what) {
    byte_buffer copy = {malloc(b->size), b->size};
    memcpy(copy.data, b->data, b->size);
    const size_t body = body_offset(&copy);
    memset(copy.data + body, value, copy.size - body);
    expect_corrupt(&copy, what);
    free(copy.data);
}

/* .bt all 0xFF: every node claims 8 inner children, deeper than 16 levels.
 * .ot all 0xFF: NaN log-odds.  All 0x00: a childless root then leftovers. */
static void overwritten_bodies_are_corrupt(void **state) {
    (void)state;
    for (int f = 0; f < 2; ++f) {
        byte_buffer b = sample_bytes(FORMATS[f]);
        body_filled_with(&b, 0xFF, "body of 0xFF");
        body_filled_with(&b, 0x00, "body of 0x00");
        free(b.data);
    }
}

static void trailing_bytes_are_corrupt(void **state) {
    (void)state;
    for (int f = 0; f < 2; ++f) {
        byte_buffer b = sample_bytes(FORMATS[f]);
        byte_buffer longer = {malloc(b.size + 4), b.size + 4};
        memcpy(longer.data, b.data, b.size);
        memset(longer.data + b.size, 0, 4);
        expect_corrupt(&longer, "4 extra bytes");
        free(longer.data);
        free(b.data);
    }
}

static int header_line_is_corrupt(const byte_buffer *b, const char *key, const char *line) {
    byte_buffer bad = replace_header_line(b, key, line);
    const int ok = load_gives(bad.data, bad.size, OPX_ERROR_CORRUPT, line);
    free(bad.data);
    return ok;
}

static void bad_header_lines_are_corrupt(void **state) {
    (void)state;
    static const char *const lines[][2] = {
        {"res ", "res nan"},   {"res ", "res -0.25"},  {"res ", "res 0"},
        {"res ", "res inf"},   {"res ", "res 1e999"},  {"res ", "res abc"},
        {"res ", "res 5e-324"}, {"res ", "res 1e-7"},  {"res ", "res 2e6"},
        {"res ", "# no res line"},
        {"size ", "size 999"}, /* not the node count */
        {"size ", "size -5"},
        {"# Octomap", "# Not an Octomap file"},
        {"# Octomap", ""},
        {"data", "dat"},
    };
    int failures = 0;
    for (int f = 0; f < 2; ++f) {
        byte_buffer b = sample_bytes(FORMATS[f]);
        for (size_t i = 0; i < sizeof lines / sizeof lines[0]; ++i)
            failures += !header_line_is_corrupt(&b, lines[i][0], lines[i][1]);
        free(b.data);
    }
    assert_int_equal(failures, 0);
}

/* Any type but OcTree: not handled (or rejected as corrupt), never loaded. */
static void other_tree_types_are_refused(void **state) {
    (void)state;
    byte_buffer b = sample_bytes(OPX_FORMAT_OT);
    byte_buffer color = replace_header_line(&b, "id ", "id ColorOcTree");
    opx_octree *out = NOT_NULL_SENTINEL;
    const opx_status status = opx_octree_load_memory(color.data, color.size, NULL, &out);
    assert_true(status == OPX_ERROR_UNSUPPORTED || status == OPX_ERROR_CORRUPT);
    assert_non_null(strstr(opx_last_error(), "ColorOcTree"));
    assert_null(out);
    free(color.data);
    free(b.data);
}

static void garbage_is_corrupt(void **state) {
    (void)state;
    const char text[] = "hello, this is not an octree\n";
    expect_load_status(text, sizeof text - 1, OPX_ERROR_CORRUPT, "text");
    unsigned char zeros[256] = {0};
    expect_load_status(zeros, sizeof zeros, OPX_ERROR_CORRUPT, "zeros");
    const char header_only[] = "# Octomap OcTree binary file\nid OcTree\nsize 3\nres 0.1\ndata";
    expect_load_status(header_only, sizeof header_only - 1, OPX_ERROR_CORRUPT, "no newline");
}

/* A chain of single inner children, `levels` deep: 16 is the finest depth,
 * so more is corrupt; a deep chain must not overflow the stack. */
static byte_buffer chain(int32_t format, int levels) {
    const char *head = format == OPX_FORMAT_BT
                           ? "# Octomap OcTree binary file\nid OcTree\nres 0.1\ndata\n"
                           : "# Octomap OcTree file\nid OcTree\nres 0.1\ndata\n";
    const size_t node = format == OPX_FORMAT_BT ? 2 : 5;
    const size_t size = strlen(head) + (size_t)(levels + 1) * node;
    byte_buffer b = {calloc(size, 1), size};
    memcpy(b.data, head, strlen(head));
    unsigned char *p = b.data + strlen(head);
    for (int i = 0; i < levels; ++i, p += node) {
        /* .bt: child 0 = 3 (inner); .ot: log-odds 0.0f then child bit 0. */
        p[format == OPX_FORMAT_BT ? 0 : 4] = format == OPX_FORMAT_BT ? 0x03 : 0x01;
    }
    if (format == OPX_FORMAT_BT) p[0] = 0x02; /* the last node: an occupied leaf child */
    return b;
}

static void trees_deeper_than_16_levels_are_corrupt(void **state) {
    (void)state;
    for (int f = 0; f < 2; ++f) {
        byte_buffer ok = chain(FORMATS[f], FORMATS[f] == OPX_FORMAT_BT ? 15 : 16);
        opx_octree *tree = NULL;
        assert_ok(opx_octree_load_memory(ok.data, ok.size, NULL, &tree));
        assert_int_equal(stats_of(tree).leaves_occupied + stats_of(tree).leaves_free, 1);
        opx_octree_destroy(tree);
        free(ok.data);
        const int too_deep[] = {17, 18, 200000};
        for (int i = 0; i < 3; ++i) {
            byte_buffer b = chain(FORMATS[f], too_deep[i]);
            expect_corrupt(&b, "too deep");
            free(b.data);
        }
    }
}

/* Flipping any one bit may give another valid map or a corrupt one, never
 * a crash, an internal error or a handle on failure. */
static int flipped_load_is_clean(const byte_buffer *b, size_t i, int bit) {
    opx_octree *out = NOT_NULL_SENTINEL;
    const opx_status status = opx_octree_load_memory(b->data, b->size, NULL, &out);
    if (status == OPX_OK) {
        if (out == NULL || out == NOT_NULL_SENTINEL) return 0;
        (void)stats_of(out);
        opx_octree_destroy(out);
        return 1;
    }
    if ((status == OPX_ERROR_CORRUPT || status == OPX_ERROR_UNSUPPORTED) && out == NULL) return 1;
    print_error("byte %zu (0x%02x) bit %d: %s: %s\n", i, b->data[i], bit, opx_status_name(status),
                opx_last_error());
    return 0;
}

static void bit_flips_load_or_fail_cleanly(void **state) {
    (void)state;
    int failures = 0;
    for (int f = 0; f < 2; ++f) {
        byte_buffer b = sample_bytes(FORMATS[f]);
        for (size_t i = 0; i < b.size; ++i) {
            for (int bit = 0; bit < 8; ++bit) {
                b.data[i] ^= (unsigned char)(1u << bit);
                failures += !flipped_load_is_clean(&b, i, bit);
                b.data[i] ^= (unsigned char)(1u << bit);
            }
        }
        free(b.data);
    }
    assert_int_equal(failures, 0);
}

/* A "res 0" line is a bad resolution, not a missing one. */
static void zero_resolution_is_named_as_such(void **state) {
    (void)state;
    byte_buffer b = sample_bytes(OPX_FORMAT_BT);
    byte_buffer bad = replace_header_line(&b, "res ", "res 0");
    assert_true(load_gives(bad.data, bad.size, OPX_ERROR_CORRUPT, "res 0"));
    assert_non_null(strstr(opx_last_error(), "resolution 0"));
    assert_null(strstr(opx_last_error(), "no \"res\" line"));
    free(bad.data);
    free(b.data);
}

/* A 3-byte payload at a denormal resolution: refused before any key is
 * computed, as an invalid argument. */
static void absurd_message_resolutions_are_refused(void **state) {
    (void)state;
    const unsigned char payload[3] = {0x01, 0x02, 0x03};
    const double resolutions[] = {5e-324, 1e-7, 2e6, 0.0, -1.0, NAN, INFINITY};
    for (size_t i = 0; i < sizeof resolutions / sizeof resolutions[0]; ++i) {
        for (int32_t binary = 0; binary < 2; ++binary) {
            opx_octree *out = NOT_NULL_SENTINEL;
            expect_failure(OPX_ERROR_INVALID_ARGUMENT, "opx_octree_load_message", "resolution",
                           opx_octree_load_message(payload, sizeof payload, binary, resolutions[i],
                                                   NULL, &out));
            assert_null(out);
        }
    }
}

static void corrupt_message_bodies_are_corrupt(void **state) {
    (void)state;
    for (int f = 0; f < 2; ++f) {
        byte_buffer b = sample_bytes(FORMATS[f]);
        const size_t body = body_offset(&b);
        const int32_t binary = FORMATS[f] == OPX_FORMAT_BT;
        for (size_t cut = 1; cut < b.size - body; ++cut) {
            opx_octree *out = NOT_NULL_SENTINEL;
            assert_status(opx_octree_load_message(b.data + body, cut, binary, RES, NULL, &out),
                          OPX_ERROR_CORRUPT);
            assert_non_null(strstr(opx_last_error(), "opx_octree_load_message"));
            assert_null(out);
        }
        memset(b.data + body, 0xFF, b.size - body);
        opx_octree *out = NOT_NULL_SENTINEL;
        assert_status(opx_octree_load_message(b.data + body, b.size - body, binary, RES, NULL, &out),
                      OPX_ERROR_CORRUPT);
        assert_null(out);
        free(b.data);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_truncation_is_corrupt),
        cmocka_unit_test(overwritten_bodies_are_corrupt),
        cmocka_unit_test(trailing_bytes_are_corrupt),
        cmocka_unit_test(bad_header_lines_are_corrupt),
        cmocka_unit_test(other_tree_types_are_refused),
        cmocka_unit_test(garbage_is_corrupt),
        cmocka_unit_test(trees_deeper_than_16_levels_are_corrupt),
        cmocka_unit_test(bit_flips_load_or_fail_cleanly),
        cmocka_unit_test(corrupt_message_bodies_are_corrupt),
        cmocka_unit_test(zero_resolution_is_named_as_such),
        cmocka_unit_test(absurd_message_resolutions_are_refused),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
