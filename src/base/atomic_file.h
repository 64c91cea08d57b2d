/*
 * Output files written whole or not at all: the one writer every file of
 * the library and the tool goes through (maps, meshes, their materials).
 *
 * A regular target (or none yet) is written to a fresh temporary in the
 * target's directory: an unpredictable name, created with O_CREAT |
 * O_EXCL | O_NOFOLLOW and the mode the umask gives, flushed and synced,
 * then renamed over the target.  Any failure removes that temporary and
 * nothing else, so the target keeps its previous content; saves of one
 * path running at once each stay whole (the last rename wins).  A target
 * given as a symbolic link is resolved first: the file it points to is
 * replaced, the link stays.  A target that is not a regular file (a
 * device, a FIFO, a terminal) is written directly and never removed.
 *
 * C99 with POSIX, compiled into the library and the tool alike.  Every
 * call returns 0, or -1 with errno saying why.
 */
#ifndef OPX_BASE_ATOMIC_FILE_H
#define OPX_BASE_ATOMIC_FILE_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct atomic_file {
    FILE *stream;    /* what the caller writes, between open and commit */
    char *target;    /* where the output lands (links resolved) */
    char *temporary; /* the file being written; NULL when writing the target directly */
} atomic_file;

/* Opens the output for path; on failure *out holds nothing to release. */
int atomic_file_open(atomic_file *out, const char *path);
/* Flushes, syncs and closes the stream, the target still untouched.  On
 * failure the temporary is removed. */
int atomic_file_finish(atomic_file *file);
/* After atomic_file_finish: renames the temporary over the target.  On
 * failure the temporary is removed. */
int atomic_file_publish(atomic_file *file);
/* atomic_file_finish, then atomic_file_publish. */
int atomic_file_commit(atomic_file *file);
/* Gives up: closes the stream if open and removes the temporary (never
 * the target).  Keeps errno. */
void atomic_file_discard(atomic_file *file);

/* Writes size bytes to path as above, in one call. */
int atomic_file_write(const char *path, const void *bytes, size_t size);

/* Creates path for writing, exclusively and without following a link
 * there (a link, even a dangling one, is EEXIST); mode 0666 less the
 * umask.  Returns the descriptor, or -1. */
int atomic_file_create_exclusive(const char *path);

#ifdef __cplusplus
}
#endif

#endif /* OPX_BASE_ATOMIC_FILE_H */
