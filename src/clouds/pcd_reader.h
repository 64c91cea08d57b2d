/*
 * A small reader of PCD v0.7 point clouds (Point Cloud Library format) for
 * the octoprox tool, tests and benchmarks.  C99, no dependencies.
 *
 * Supported: DATA ascii and DATA binary (little-endian, as PCL writes it),
 * with fields x, y and z stored as float32 or float64 (TYPE F, SIZE 4 or 8,
 * COUNT 1; float64 values are rounded to float32); any other fields (rgb,
 * rgba, normals, intensity...) are skipped.  DATA binary_compressed (LZF) is rejected with
 * a clear message: convert the file to binary first (pcl_convert_pcd_ascii_binary).
 * The header is checked strictly (whole numbers, WIDTH and HEIGHT below
 * 2^32, at most 32 fields); a header announcing more points than the rest
 * of the file can hold is an error before anything is allocated for them.
 */
#ifndef OPX_CLOUDS_PCD_READER_H
#define OPX_CLOUDS_PCD_READER_H

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
    double viewpoint[7];   /* VIEWPOINT: tx ty tz qw qx qy qz (PCD order) */
    char data_format[24];  /* "ascii" or "binary" */
} pcd_cloud;

/*
 * Reads a PCD file into *out (zeroed first).  Returns 0 on success.  On
 * failure returns -1, leaves *out empty and writes a message naming the
 * file and the problem into error (error_size bytes, may be 0).
 */
int pcd_read_file(const char *path, pcd_cloud *out, char *error, size_t error_size);

/* Frees the points of a cloud read by pcd_read_file; NULL is a no-op. */
void pcd_free(pcd_cloud *cloud);

#ifdef __cplusplus
}
#endif

#endif /* OPX_CLOUDS_PCD_READER_H */
