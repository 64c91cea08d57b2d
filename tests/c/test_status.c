/* Status names, versions and the thread-local last error. */
#define _POSIX_C_SOURCE 200809L /* pthreads under -std=c99 */

#include "opx_test.h"

#include <limits.h>
#include <pthread.h>

/* Must run first: no call has failed on this thread yet. */
static void last_error_is_empty_before_any_failure(void **state) {
    (void)state;
    const char *message = opx_last_error();
    assert_non_null(message);
    assert_string_equal(message, "");
}

static void status_names_match_every_code(void **state) {
    (void)state;
    assert_string_equal(opx_status_name(OPX_OK), "OPX_OK");
    assert_string_equal(opx_status_name(OPX_ERROR_INVALID_ARGUMENT), "OPX_ERROR_INVALID_ARGUMENT");
    assert_string_equal(opx_status_name(OPX_ERROR_OUT_OF_MEMORY), "OPX_ERROR_OUT_OF_MEMORY");
    assert_string_equal(opx_status_name(OPX_ERROR_VERSION), "OPX_ERROR_VERSION");
    assert_string_equal(opx_status_name(OPX_ERROR_BUFFER_TOO_SMALL), "OPX_ERROR_BUFFER_TOO_SMALL");
    assert_string_equal(opx_status_name(OPX_ERROR_UNSUPPORTED), "OPX_ERROR_UNSUPPORTED");
    assert_string_equal(opx_status_name(OPX_ERROR_IO), "OPX_ERROR_IO");
    assert_string_equal(opx_status_name(OPX_ERROR_CORRUPT), "OPX_ERROR_CORRUPT");
    assert_string_equal(opx_status_name(OPX_ERROR_INTERNAL), "OPX_ERROR_INTERNAL");
}

/* The codes are part of the ABI: never renumbered. */
static void status_codes_keep_their_values(void **state) {
    (void)state;
    assert_int_equal(OPX_OK, 0);
    assert_int_equal(OPX_ERROR_INVALID_ARGUMENT, -1);
    assert_int_equal(OPX_ERROR_OUT_OF_MEMORY, -2);
    assert_int_equal(OPX_ERROR_VERSION, -3);
    assert_int_equal(OPX_ERROR_BUFFER_TOO_SMALL, -4);
    assert_int_equal(OPX_ERROR_UNSUPPORTED, -5);
    assert_int_equal(OPX_ERROR_IO, -6);
    assert_int_equal(OPX_ERROR_CORRUPT, -7);
    assert_int_equal(OPX_ERROR_INTERNAL, -8);
}

static void unknown_status_has_a_name(void **state) {
    (void)state;
    const opx_status unknown[] = {1, 42, -9, -100, INT32_MIN, INT32_MAX};
    for (size_t i = 0; i < sizeof unknown / sizeof unknown[0]; ++i)
        assert_string_equal(opx_status_name(unknown[i]), "OPX_UNKNOWN_STATUS");
}

static void version_matches_the_header(void **state) {
    (void)state;
    char expected[64];
    snprintf(expected, sizeof expected, "%d.%d.%d", OPX_VERSION_MAJOR, OPX_VERSION_MINOR,
             OPX_VERSION_PATCH);
    assert_non_null(opx_version());
    assert_string_equal(opx_version(), expected);
    assert_int_equal(opx_version_number(), OPX_VERSION_NUMBER);
    assert_int_equal(OPX_VERSION_NUMBER,
                     OPX_VERSION_MAJOR * 10000 + OPX_VERSION_MINOR * 100 + OPX_VERSION_PATCH);
}

static void last_error_names_function_and_argument(void **state) {
    (void)state;
    assert_int_equal(opx_octree_create(NULL, NULL), OPX_ERROR_INVALID_ARGUMENT);
    const char *message = opx_last_error();
    assert_non_null(strstr(message, "opx_octree_create"));
    assert_non_null(strstr(message, "out"));
}

/* "Valid until the next failing call": a successful call keeps it. */
static void successful_call_keeps_the_last_error(void **state) {
    (void)state;
    assert_int_equal(opx_octree_clear(NULL), OPX_ERROR_INVALID_ARGUMENT);
    char saved[512];
    snprintf(saved, sizeof saved, "%s", opx_last_error());
    assert_true(strlen(saved) > 0);

    opx_octree *tree = new_tree(0.1);
    assert_ok(opx_octree_clear(tree));
    opx_octree_destroy(tree);
    assert_string_equal(opx_last_error(), saved);
}

static void *fail_on_another_thread(void *arg) {
    (void)arg;
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = -1.0;
    opx_octree *tree = NULL;
    static int result;
    result = opx_octree_create(&options, &tree) == OPX_ERROR_INVALID_ARGUMENT &&
             strstr(opx_last_error(), "resolution") != NULL;
    return &result;
}

/* The message is per thread: another thread's failure leaves ours alone. */
static void last_error_is_thread_local(void **state) {
    (void)state;
    assert_int_equal(opx_octree_clear(NULL), OPX_ERROR_INVALID_ARGUMENT);
    char saved[512];
    snprintf(saved, sizeof saved, "%s", opx_last_error());

    pthread_t thread;
    void *result = NULL;
    assert_int_equal(pthread_create(&thread, NULL, fail_on_another_thread, NULL), 0);
    assert_int_equal(pthread_join(thread, &result), 0);
    assert_int_equal(*(int *)result, 1);
    assert_string_equal(opx_last_error(), saved);
}

static void destroy_null_is_a_no_op(void **state) {
    (void)state;
    opx_octree_destroy(NULL);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(last_error_is_empty_before_any_failure),
        cmocka_unit_test(status_names_match_every_code),
        cmocka_unit_test(status_codes_keep_their_values),
        cmocka_unit_test(unknown_status_has_a_name),
        cmocka_unit_test(version_matches_the_header),
        cmocka_unit_test(last_error_names_function_and_argument),
        cmocka_unit_test(successful_call_keeps_the_last_error),
        cmocka_unit_test(last_error_is_thread_local),
        cmocka_unit_test(destroy_null_is_a_no_op),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
