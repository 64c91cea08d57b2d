/*
 * Point clouds from files, whatever their format: .pcd (PCD v0.7: ascii,
 * binary or binary_compressed) and .ply (ascii or binary_little_endian),
 * picked by extension.  C99.
 */
#ifndef OPX_CLOUDS_CLOUD_FILE_H
#define OPX_CLOUDS_CLOUD_FILE_H

#include "cloud_status.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CLOUD_FILE_PCD 1
#define CLOUD_FILE_PLY 2

typedef struct cloud_points {
    float *xyz;           /* count points, packed x y z (the file's frame) */
    size_t count;
    size_t finite_count;
    int kind;             /* CLOUD_FILE_PCD or CLOUD_FILE_PLY */
    char encoding[32];    /* "ascii", "binary", "binary_compressed" (PCD), "binary_little_endian" (PLY) */
    uint64_t width;       /* PCD: WIDTH (columns of an organized cloud); PLY: count */
    uint64_t height;      /* PCD: HEIGHT (rows; 1 when unorganized); PLY: 1 */
    double viewpoint[7];  /* PCD VIEWPOINT: tx ty tz qw qx qy qz; else 0 0 0 1 0 0 0 */
    int has_viewpoint;    /* 1 when a PCD header has a VIEWPOINT line */
    char format[40];      /* kind and encoding for people: "pcd binary", "ply ascii" */
} cloud_points;

/* 1 when the path ends in .pcd or .ply (any case), else 0. */
int cloud_file_supported(const char *path);

/* Reads a cloud; 0 on success, else a CLOUD_ERROR_* with a message naming
 * the file (an unknown extension: CLOUD_ERROR_UNSUPPORTED). */
int cloud_read_file(const char *path, cloud_points *out, char *error, size_t error_size);
void cloud_free(cloud_points *cloud);

#ifdef __cplusplus
}
#endif

#endif /* OPX_CLOUDS_CLOUD_FILE_H */
