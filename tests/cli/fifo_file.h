/* Bytes served through a named pipe, as a shell's <(...) does: a file
 * whose size the readers cannot know beforehand. */
#ifndef OPX_TESTS_FIFO_FILE_H
#define OPX_TESTS_FIFO_FILE_H

#include <stddef.h>
#include <sys/types.h>

/* Makes scratch_dir()/name a named pipe and forks a writer of the bytes
 * into it; returns the pipe's path (*writer: wait for it with
 * finish_fifo). */
const char *serve_through_fifo(const char *name, const void *bytes, size_t size, pid_t *writer);
void finish_fifo(pid_t writer);

#endif /* OPX_TESTS_FIFO_FILE_H */
