/*
 * Point clouds from files, whatever their format: .pcd (PCD v0.7, ascii or
 * binary) and .ply (ascii or binary_little_endian), picked by extension.
 * C99, no dependencies.
 */
#ifndef OPX_CLOUDS_CLOUD_FILE_H
#define OPX_CLOUDS_CLOUD_FILE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cloud_points {
    float *xyz;           /* count points, packed x y z (the file's frame) */
    size_t count;
    size_t finite_count;
    char format[40];      /* e.g. "pcd binary", "ply ascii" */
} cloud_points;

/* 1 when the path ends in .pcd or .ply (any case), else 0. */
int cloud_file_supported(const char *path);

/* Reads a cloud; 0 on success, -1 with a message naming the file. */
int cloud_read_file(const char *path, cloud_points *out, char *error, size_t error_size);
void cloud_free(cloud_points *cloud);

#ifdef __cplusplus
}
#endif

#endif /* OPX_CLOUDS_CLOUD_FILE_H */
