/* Output files written whole or not at all: see atomic_file.h. */
#define _XOPEN_SOURCE 700

#include "atomic_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* Names taken by other files (another save's temporary) are skipped; this
 * many in a row means something else is wrong. */
#define TEMPORARY_ATTEMPTS 64
/* The target's name kept in its temporary's, so that the temporary's stays
 * within NAME_MAX (255) with the dot, the random part and ".tmp". */
#define NAME_KEPT 200

static void release(atomic_file *file) {
    free(file->target);
    free(file->temporary);
    memset(file, 0, sizeof *file);
}

/* 64 unpredictable bits: the kernel's random numbers, or where they are
 * unavailable the clock, the process and the stack, mixed (SplitMix64's
 * finaliser). */
static uint64_t random_bits(void) {
    uint64_t bits = 0;
    struct timespec now;
    if (getrandom(&bits, sizeof bits, GRND_NONBLOCK) == (ssize_t)sizeof bits) return bits;
    clock_gettime(CLOCK_REALTIME, &now);
    bits = (uint64_t)now.tv_nsec ^ (uint64_t)now.tv_sec << 30 ^ (uint64_t)getpid() << 40 ^ (uint64_t)(uintptr_t)&now;
    bits = (bits ^ bits >> 30) * 0xbf58476d1ce4e5b9u;
    bits = (bits ^ bits >> 27) * 0x94d049bb133111ebu;
    return bits ^ bits >> 31;
}

/* "DIR/.NAME.<16 hex digits>.tmp" beside target "DIR/NAME"; NULL when out
 * of memory. */
static char *temporary_name(const char *target) {
    const char *slash = strrchr(target, '/');
    const size_t directory = slash != NULL ? (size_t)(slash - target) + 1 : 0;
    const size_t name = strlen(target + directory) < NAME_KEPT ? strlen(target + directory) : NAME_KEPT;
    const size_t size = directory + name + 32;
    char *out = malloc(size);
    if (out != NULL)
        snprintf(out, size, "%.*s.%.*s.%016llx.tmp", (int)directory, target, (int)name, target + directory,
                 (unsigned long long)random_bits());
    return out;
}

int atomic_file_create_exclusive(const char *path) {
    /* O_EXCL alone already fails on any link; O_NOFOLLOW says so twice. */
    return open(path, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
}

/* What an output for path replaces: path, or the file a link there points
 * to (a link pointing nowhere is ENOENT).  *regular is 0 for a device, a
 * FIFO or a socket; a directory is EISDIR. */
static int resolve_target(const char *path, char **out, int *regular) {
    struct stat status;
    int link;
    *out = NULL;
    *regular = 1;
    if (lstat(path, &status) != 0) {
        if (errno != ENOENT) return -1;
        *out = strdup(path); /* a new file */
        return *out != NULL ? 0 : -1;
    }
    link = S_ISLNK(status.st_mode);
    if (link && stat(path, &status) != 0) return -1;
    if (S_ISDIR(status.st_mode)) {
        errno = EISDIR;
        return -1;
    }
    *regular = S_ISREG(status.st_mode);
    *out = link && *regular ? realpath(path, NULL) : strdup(path);
    return *out != NULL ? 0 : -1;
}

/* A fresh temporary beside the target; the descriptor, or -1 with
 * file->temporary NULL (a name this call did not create is never kept, so
 * never removed). */
static int open_temporary(atomic_file *file) {
    int attempt;
    for (attempt = 0; attempt < TEMPORARY_ATTEMPTS; ++attempt) {
        int descriptor;
        if ((file->temporary = temporary_name(file->target)) == NULL) return -1;
        descriptor = atomic_file_create_exclusive(file->temporary);
        if (descriptor >= 0) return descriptor;
        free(file->temporary);
        file->temporary = NULL;
        if (errno != EEXIST) return -1;
    }
    errno = EEXIST;
    return -1;
}

int atomic_file_open(atomic_file *out, const char *path) {
    int regular, descriptor = -1;
    memset(out, 0, sizeof *out);
    if (resolve_target(path, &out->target, &regular) == 0)
        descriptor = regular ? open_temporary(out) : open(out->target, O_WRONLY | O_NOCTTY | O_CLOEXEC);
    if (descriptor >= 0 && (out->stream = fdopen(descriptor, "wb")) != NULL) return 0;
    {
        const int error = errno;
        if (descriptor >= 0) close(descriptor);
        if (out->temporary != NULL) unlink(out->temporary);
        release(out);
        errno = error;
    }
    return -1;
}

int atomic_file_finish(atomic_file *file) {
    FILE *stream = file->stream;
    int error = errno; /* a failed write's, when one failed */
    int failed = ferror(stream) != 0;
    if (!failed && fflush(stream) != 0) failed = 1, error = errno;
    /* A device or a FIFO has nothing to sync (fsync fails on some). */
    if (!failed && file->temporary != NULL && fsync(fileno(stream)) != 0) failed = 1, error = errno;
    file->stream = NULL;
    if (fclose(stream) != 0 && !failed) failed = 1, error = errno;
    if (!failed) return 0;
    errno = error != 0 ? error : EIO;
    atomic_file_discard(file);
    return -1;
}

/* Makes a rename in the directory of path durable; best effort. */
static void sync_directory(const char *path) {
    const char *slash = strrchr(path, '/');
    char *directory = slash == NULL ? strdup(".") : strndup(path, slash == path ? 1 : (size_t)(slash - path));
    int descriptor = directory != NULL ? open(directory, O_RDONLY | O_DIRECTORY | O_CLOEXEC) : -1;
    if (descriptor >= 0) {
        fsync(descriptor);
        close(descriptor);
    }
    free(directory);
}

int atomic_file_publish(atomic_file *file) {
    if (file->temporary != NULL) {
        if (rename(file->temporary, file->target) != 0) {
            atomic_file_discard(file);
            return -1;
        }
        sync_directory(file->target);
    }
    release(file);
    return 0;
}

int atomic_file_commit(atomic_file *file) {
    return atomic_file_finish(file) == 0 ? atomic_file_publish(file) : -1;
}

void atomic_file_discard(atomic_file *file) {
    const int error = errno;
    if (file->stream != NULL) fclose(file->stream);
    if (file->temporary != NULL) unlink(file->temporary);
    release(file);
    errno = error;
}

int atomic_file_write(const char *path, const void *bytes, size_t size) {
    atomic_file file;
    if (atomic_file_open(&file, path) != 0) return -1;
    if (size > 0 && fwrite(bytes, 1, size, file.stream) != size) {
        atomic_file_discard(&file);
        return -1;
    }
    return atomic_file_commit(&file);
}
