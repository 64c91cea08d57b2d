/*
 * A small reader of PCD v0.7 point clouds (Point Cloud Library format) for
 * the library (opx_point_cloud_read_file), the octoprox tool, tests and
 * benchmarks.  C99; liblzf for compressed data.
 *
 * Supported: DATA ascii, DATA binary (little-endian, as PCL writes it) and
 * DATA binary_compressed (LZF through liblzf, see pcd_compressed.h),
 * with fields x, y and z stored as float32 or float64 (TYPE F, SIZE 4 or
 * 8, COUNT 1; float64 values are rounded to float32); any other fields
 * (rgb, rgba, normals, intensity...) are skipped.  The header is checked strictly (whole
 * numbers, WIDTH and HEIGHT below 2^32, at most 32 fields, a VIEWPOINT of
 * finite numbers); a header announcing more points than the rest of the
 * file can hold is an error before anything is allocated for them.
 */
#ifndef OPX_CLOUDS_PCD_READER_H
#define OPX_CLOUDS_PCD_READER_H

#include "cloud_status.h"

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct pcd_cloud {
    float *xyz;            /* count points, packed x y z; NaN points are kept */
    size_t count;          /* width * height */
    size_t finite_count;   /* points whose x, y and z are all finite */
    uint32_t width;        /* columns of an organized cloud; count when unorganized */
    uint32_t height;       /* rows; 1 when unorganized */
    double viewpoint[7];   /* VIEWPOINT: tx ty tz qw qx qy qz (PCD order); 0 0 0 1 0 0 0 without one */
    int has_viewpoint;     /* 1 when the header has a VIEWPOINT line */
    char data_format[24];  /* "ascii", "binary" or "binary_compressed" */
} pcd_cloud;

/*
 * Reads a PCD file into *out (zeroed first).  Returns 0 on success.  On
 * failure returns a CLOUD_ERROR_* (cloud_status.h; all negative), leaves *out
 * empty and writes a message naming the file and the problem into error
 * (error_size bytes, may be 0).
 */
int pcd_read_file(const char *path, pcd_cloud *out, char *error, size_t error_size);

/* Frees the points of a cloud read by pcd_read_file; NULL is a no-op. */
void pcd_free(pcd_cloud *cloud);

#ifdef __cplusplus
}
#endif

#endif /* OPX_CLOUDS_PCD_READER_H */
