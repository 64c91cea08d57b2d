/*
 * A small reader of the vertices of PLY files (Stanford polygon format) as
 * point clouds.  C99, no dependencies.
 *
 * Supported: format ascii 1.0 and binary_little_endian 1.0; the `vertex`
 * element's x, y and z as float/float32 or double/float64 (doubles are
 * rounded to float32); any other vertex properties (colours, normals) are
 * skipped.  Elements before `vertex` are skipped (scalar and list
 * properties, lists of at most a million items); elements after it
 * (faces) are not read.  binary_big_endian is rejected by name.  An
 * element announcing more rows than the rest of the file can hold is an
 * error before anything is read or allocated for it.
 */
#ifndef OPX_CLOUDS_PLY_READER_H
#define OPX_CLOUDS_PLY_READER_H

#include "cloud_status.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct ply_cloud {
    float *xyz;           /* count points, packed x y z */
    size_t count;         /* vertices */
    size_t finite_count;  /* vertices whose x, y and z are all finite */
    char format[32];      /* "ascii" or "binary_little_endian" */
} ply_cloud;

/*
 * Reads the vertices of a PLY file into *out (zeroed first).  Returns 0 on
 * success.  On failure returns a CLOUD_ERROR_* (cloud_status.h; all
 * negative), leaves *out empty and writes a message naming the file and
 * the problem into error (error_size bytes, may be 0).
 */
int ply_read_file(const char *path, ply_cloud *out, char *error, size_t error_size);

/* Frees the points of a cloud read by ply_read_file; NULL is a no-op. */
void ply_free(ply_cloud *cloud);

#ifdef __cplusplus
}
#endif

#endif /* OPX_CLOUDS_PLY_READER_H */
