/* The scratch file of a fuzz process: see fuzz_file.h. */
#define _GNU_SOURCE /* mkstemps */
#include "fuzz_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char scratch_path[256];
static int scratch_fd = -1;

static void remove_scratch_file(void) {
    if (scratch_fd >= 0) unlink(scratch_path);
}

/* /dev/shm when there is one: the file never reaches a disk. */
static void make_scratch_file(const char *suffix) {
    const char *folder = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    snprintf(scratch_path, sizeof scratch_path, "%s/opx-fuzz-XXXXXX%s", folder, suffix);
    scratch_fd = mkstemps(scratch_path, (int)strlen(suffix));
    if (scratch_fd < 0) {
        perror("fuzz_scratch_file: mkstemps");
        abort();
    }
    atexit(remove_scratch_file);
}

const char *fuzz_scratch_file(const char *suffix, const uint8_t *data, size_t size) {
    if (scratch_fd < 0) make_scratch_file(suffix);
    size_t done = 0;
    if (ftruncate(scratch_fd, 0) != 0) abort();
    while (done < size) {
        const ssize_t written = pwrite(scratch_fd, data + done, size - done, (off_t)done);
        if (written <= 0) {
            perror("fuzz_scratch_file: pwrite");
            abort();
        }
        done += (size_t)written;
    }
    return scratch_path;
}

size_t fuzz_count_finite(const float *xyz, size_t count) {
    size_t finite = 0;
    for (size_t i = 0; i < count; ++i)
        finite += isfinite(xyz[3 * i]) && isfinite(xyz[3 * i + 1]) && isfinite(xyz[3 * i + 2]);
    return finite;
}
