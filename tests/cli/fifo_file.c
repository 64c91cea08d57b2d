/* Bytes through a named pipe: see fifo_file.h. */
#define _POSIX_C_SOURCE 200809L

#include "fifo_file.h"

#include "cli_run.h"

#include <fcntl.h>
#include <setjmp.h>
#include <stdarg.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmocka.h>

const char *serve_through_fifo(const char *name, const void *bytes, size_t size, pid_t *writer) {
    const char *path = scratch_path(name);
    unlink(path);
    if (mkfifo(path, 0600) != 0) fail_msg("cannot make the pipe %s", path);
    *writer = fork();
    if (*writer < 0) fail_msg("cannot fork");
    if (*writer == 0) {
        const int fd = open(path, O_WRONLY);
        const char *at = bytes;
        while (fd >= 0 && size > 0) {
            const ssize_t written = write(fd, at, size);
            if (written <= 0) break;
            at += written;
            size -= (size_t)written;
        }
        _exit(0);
    }
    return path;
}

void finish_fifo(pid_t writer) {
    int status;
    waitpid(writer, &status, 0);
}
