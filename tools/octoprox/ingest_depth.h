/*
 * Depth images in `octoprox ingest`: the camera options (--intrinsics,
 * --depth-scale), their checks against the inputs, and the insert of one
 * 16-bit PNG or TIFF file.
 */
#ifndef OPX_TOOLS_INGEST_DEPTH_H
#define OPX_TOOLS_INGEST_DEPTH_H

#include "cli.h"

#include <stddef.h>

/* What the insert of one input (cloud or depth image) did. */
typedef struct ingest_result {
    char format[40];
    size_t points; /* the cloud's points, or the image's pixels */
    opx_insert_report report;
    double insert_ms;
    opx_pose sensor_pose;    /* the frame of the input's points, in the map frame */
    const char *pose_source; /* "--sensor-pose", "VIEWPOINT" or "default" */
} ingest_result;

typedef struct ingest_camera {
    opx_camera_intrinsics intrinsics;
    int has_intrinsics;
    double depth_scale; /* depth units per metre; 0: not given */
} ingest_camera;

/* Parses --intrinsics (value) or --depth-scale (value) at args->index into
 * camera: 1 when taken, 0 when the option is another one, or a usage exit
 * code (>= 2) when its value is bad. */
int ingest_camera_option(cli_args *args, ingest_camera *camera);

/* 1 for a depth image file name (.png, .tif, .tiff). */
int ingest_is_depth_image(const char *path);

/* -1 when the camera options and the inputs go together (a depth image
 * needs both options, the options need a depth image), else the usage
 * exit code after a message. */
int ingest_check_camera(const ingest_camera *camera, const char *const *inputs, int count);

/* Reads the depth image at path and inserts it: -1 on success, else the
 * exit code after a message. */
int ingest_depth_file(const char *path, opx_octree *map, const ingest_camera *camera,
                      const opx_insert_options *insert, ingest_result *result);

#endif /* OPX_TOOLS_INGEST_DEPTH_H */
