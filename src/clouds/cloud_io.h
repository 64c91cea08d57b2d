/*
 * What the PCD and PLY readers share (internal to opx_clouds): messages,
 * strict header numbers, bounded words and lines, the bytes a file has
 * left, a growing array of points, counting finite points, and opening a
 * file around a format's reader.
 */
#ifndef OPX_CLOUDS_CLOUD_IO_H
#define OPX_CLOUDS_CLOUD_IO_H

#include "cloud_status.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* The most points a cloud may hold: its packed x y z floats must have a
 * size that fits in size_t. */
#define CLOUD_MAX_POINTS (SIZE_MAX / (3 * sizeof(float)))

/* vsnprintf into error (nothing when error is NULL or error_size 0). */
void cloud_set_error(char *error, size_t error_size, const char *format, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* A count from a header: decimal digits only (no sign, no blank), at most
 * `max`.  0 and *out set, or -1 when the word is not such a number. */
int cloud_parse_count(const char *word, uint64_t max, uint64_t *out);

/* Bytes from the file's position to its end.  0 and *out set for a
 * regular file; -1 when the size is unknown (a pipe, a device). */
int cloud_bytes_left(FILE *file, uint64_t *out);

/* One header line into line (size bytes), newline kept.  0; -1 at the end
 * of the file; -2 when the line does not fit in size - 1 bytes. */
int cloud_read_line(FILE *file, char *line, size_t size);

/* The next whitespace-separated word into word (size bytes).  0; -1 at
 * the end of the file; -2 when the word does not fit in size - 1 bytes. */
int cloud_read_word(FILE *file, char *word, size_t size);

/* Makes *xyz (room for *capacity points) hold at least `needed` points,
 * growing geometrically but never past `total` (the points the file
 * announces, at most CLOUD_MAX_POINTS).  0, or -1 out of memory (*xyz
 * is then unchanged). */
int cloud_reserve_points(float **xyz, size_t *capacity, size_t needed, size_t total);

/* The room to allocate before reading `total` announced points: all of
 * them when the file's size bounded them (size_known), else a first
 * slice that grows as the points really arrive.  At least 1. */
size_t cloud_first_capacity(size_t total, int size_known);

/* Points of `count` packed x y z whose three coordinates are finite. */
size_t cloud_count_finite(const float *xyz, size_t count);

/* Reads an open file into `out`; 0, or a CLOUD_ERROR_* with the reason. */
typedef int (*cloud_format_reader)(FILE *file, void *out, char *reason, size_t reason_size);

/* Opens `path`, runs `read` on it, closes it; on failure the message
 * names the file ("PATH: reason").  0 on success, else the CLOUD_ERROR_*
 * of the failure (CLOUD_ERROR_IO when the file cannot be opened). */
int cloud_read_path(const char *path, cloud_format_reader read, void *out, char *error, size_t error_size);

#endif /* OPX_CLOUDS_CLOUD_IO_H */
