/*
 * What the PCD and PLY readers share (internal to opx_clouds): messages,
 * counting finite points, and opening a file around a format's reader.
 */
#ifndef OPX_CLOUDS_CLOUD_IO_H
#define OPX_CLOUDS_CLOUD_IO_H

#include <stddef.h>
#include <stdio.h>

/* vsnprintf into error (nothing when error is NULL or error_size 0). */
void cloud_set_error(char *error, size_t error_size, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Points of `count` packed x y z whose three coordinates are finite. */
size_t cloud_count_finite(const float *xyz, size_t count);

/* Reads an open file into `out`; 0, or -1 with the reason. */
typedef int (*cloud_format_reader)(FILE *file, void *out, char *reason, size_t reason_size);

/* Opens `path`, runs `read` on it, closes it; on failure the message
 * names the file ("PATH: reason").  0 on success, -1 on failure. */
int cloud_read_path(const char *path, cloud_format_reader read, void *out, char *error, size_t error_size);

#endif /* OPX_CLOUDS_CLOUD_IO_H */
