/*
 * The shared data for C tests: the folder in $OPX_DATA_DIR, else
 * OPX_DEFAULT_DATA_DIR (a compile definition), and a file in it or the
 * whole test skipped (exit 77, the tests' SKIP_RETURN_CODE), or failed
 * when OPX_REQUIRE_DATA=1.
 */
#ifndef OPX_DATA_TEST_H
#define OPX_DATA_TEST_H

#include <stdio.h>
#include <stdlib.h>
#include <sys/stat.h>

static inline const char *data_dir(void) {
    const char *env = getenv("OPX_DATA_DIR");
    return env != NULL && env[0] != '\0' ? env : OPX_DEFAULT_DATA_DIR;
}

/* With OPX_REQUIRE_DATA=1 (CI sets it) absent data fails a test instead
 * of skipping it. */
static inline int data_required(void) {
    const char *env = getenv("OPX_REQUIRE_DATA");
    return env != NULL && env[0] == '1' && env[1] == '\0';
}

/* Ends a test whose data is absent: skipped (77), or failed (1) when the
 * data is required. */
static inline void exit_without_data(const char *missing) {
    if (data_required()) {
        printf("FAIL: %s not found and OPX_REQUIRE_DATA=1: the shared data is required\n", missing);
        fflush(stdout);
        exit(1);
    }
    printf("SKIP: %s not found, set OPX_DATA_DIR to the shared data folder\n", missing);
    fflush(stdout);
    exit(77);
}

/* Fills path with data_dir()/relative, or ends the test (exit_without_data). */
static inline void require_data_file(const char *relative, char *path, size_t size) {
    struct stat info;
    snprintf(path, size, "%s/%s", data_dir(), relative);
    if (stat(path, &info) != 0) exit_without_data(path);
}

#endif
