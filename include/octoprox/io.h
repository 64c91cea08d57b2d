/*
 * Point clouds from files: the PCD and PLY readers of the `octoprox` tool,
 * for callers who hold clouds as files (the Python and Rust bindings read
 * through these too).
 *
 * Formats, told by the file name's extension (any case):
 *   - .pcd, PCD v0.7 (Point Cloud Library): DATA ascii, binary and
 *     binary_compressed (LZF, as PCL writes it); fields x, y and z as
 *     float32 or float64 (TYPE F, SIZE 4 or 8, COUNT 1), other fields
 *     (rgb, normals, intensity...) skipped.  WIDTH and HEIGHT give an
 *     organized cloud's columns and rows; VIEWPOINT is reported.
 *   - .ply, the vertices of a PLY file: format ascii or
 *     binary_little_endian; vertex x, y and z as float or double, other
 *     properties skipped, other elements (faces) not read.
 * Points are float32 (float64 values are rounded), in the file's order
 * (an organized cloud row after row), non-finite points (no return)
 * included, in the frame of the file: for a camera cloud usually its
 * optical frame (z forward, x right, y down).
 *
 * Usage: read once, ask for the info, copy the points into a buffer of
 * info.point_count points, destroy:
 *
 *     opx_point_cloud *cloud = NULL;
 *     opx_point_cloud_info info = OPX_POINT_CLOUD_INFO_INIT;
 *     if (opx_point_cloud_read_file("frame.pcd", &cloud) == OPX_OK &&
 *         opx_point_cloud_get_info(cloud, &info) == OPX_OK) {
 *         float *xyz = malloc(info.point_count * 3 * sizeof(float) + 1);
 *         size_t n = 0;
 *         opx_point_cloud_get_points(cloud, xyz, info.point_count, 0, &n);
 *         ...
 *     }
 *     opx_point_cloud_destroy(cloud);
 *
 * A handle rather than a size query followed by a read: the file is read
 * once, and what the info says is what the points are.
 */
#ifndef OCTOPROX_IO_H
#define OCTOPROX_IO_H

#include "common.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A point cloud read from a file; owned by the caller (destroy it). */
typedef struct opx_point_cloud opx_point_cloud;

/* File formats. */
#define OPX_CLOUD_FORMAT_PCD 1
#define OPX_CLOUD_FORMAT_PLY 2

/* How the points are stored in the file. */
#define OPX_CLOUD_ENCODING_ASCII 1
#define OPX_CLOUD_ENCODING_BINARY 2            /**< PCD binary; PLY binary_little_endian */
#define OPX_CLOUD_ENCODING_BINARY_COMPRESSED 3 /**< PCD binary_compressed (LZF) */

typedef struct opx_point_cloud_info {
    uint32_t struct_size;
    int32_t format;        /**< OPX_CLOUD_FORMAT_* */
    int32_t encoding;      /**< OPX_CLOUD_ENCODING_* */
    int32_t has_viewpoint; /**< 1 when the PCD header has a VIEWPOINT line */
    uint64_t point_count;  /**< every point, non-finite ones included */
    uint64_t finite_count; /**< points whose x, y and z are all finite */
    uint64_t width;        /**< PCD WIDTH: columns of an organized cloud, else point_count; PLY: point_count */
    uint64_t height;       /**< PCD HEIGHT: rows of an organized cloud, else 1; PLY: 1 */
    /** The PCD VIEWPOINT (written tx ty tz qw qx qy qz) as a pose in ROS
     * order, as written (not normalised): the pose of the cloud's frame
     * (the sensor's) in the frame the cloud is to be placed in, as PCL's
     * viewer applies it; `octoprox ingest` takes it as the sensor pose.
     * Identity without a VIEWPOINT line and for PLY. */
    opx_pose viewpoint;
} opx_point_cloud_info;

#define OPX_POINT_CLOUD_INFO_INIT {sizeof(opx_point_cloud_info), 0, 0, 0, 0, 0, 0, 0, OPX_POSE_IDENTITY}
OPX_API opx_status opx_point_cloud_info_init(opx_point_cloud_info *info, size_t size);

/**
 * Reads a .pcd or .ply file (see above) into a new cloud; *out is NULL on
 * failure.  Errors, the message naming the file and what is wrong:
 * OPX_ERROR_IO (the file cannot be opened), OPX_ERROR_CORRUPT (a
 * malformed or truncated header or body, sizes that disagree, corrupt LZF
 * data), OPX_ERROR_UNSUPPORTED (another extension, PLY
 * binary_big_endian, x y z stored as integers), OPX_ERROR_OUT_OF_MEMORY,
 * OPX_ERROR_INVALID_ARGUMENT (NULLs).  A header announcing more points
 * than the rest of the file can hold fails before anything is allocated
 * for them.
 */
OPX_API opx_status opx_point_cloud_read_file(const char *path, opx_point_cloud **out);
/** Frees the cloud; NULL is a no-op. */
OPX_API void opx_point_cloud_destroy(opx_point_cloud *cloud);

OPX_API opx_status opx_point_cloud_get_info(const opx_point_cloud *cloud, opx_point_cloud_info *out);

/**
 * Copies the points, x y z float32 each (the file's frame, metres as the
 * file has them), point i at (char *)out_xyz + i * stride (0: packed, 12
 * bytes; else at least 12 and a multiple of 4, e.g. 16 for x y z w).
 * *out_count gets the point count; a capacity (in points) below it is
 * OPX_ERROR_BUFFER_TOO_SMALL and writes nothing (out_xyz may then be NULL).
 */
OPX_API opx_status opx_point_cloud_get_points(const opx_point_cloud *cloud, float *out_xyz,
                                              size_t capacity, size_t stride, size_t *out_count);

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_IO_H */
