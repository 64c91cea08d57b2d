/*
 * The shared data for C tests: the folder in $OPX_DATA_DIR, else
 * OPX_DEFAULT_DATA_DIR (a compile definition), and a file in it or the
 * whole test skipped (exit 77, the tests' SKIP_RETURN_CODE).
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

/* Fills path with data_dir()/relative, or skips the whole test (77). */
static inline void require_data_file(const char *relative, char *path, size_t size) {
    struct stat info;
    snprintf(path, size, "%s/%s", data_dir(), relative);
    if (stat(path, &info) != 0) {
        printf("SKIP: %s not found, set OPX_DATA_DIR to the shared data folder\n", path);
        fflush(stdout);
        exit(77);
    }
}

#endif
