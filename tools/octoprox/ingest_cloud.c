/* Point clouds in `octoprox ingest`: see ingest_cloud.h. */
#include "ingest_cloud.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The optical frame in the z-up body frame (x y z w): its z axis is the
 * body's x, its x the body's -y, its y the body's -z. */
static const double kOpticalInBody[4] = {-0.5, 0.5, -0.5, 0.5};

/* a * b, quaternions x y z w (Hamilton). */
static void multiply(const double a[4], const double b[4], double out[4]) {
    out[0] = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
    out[1] = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
    out[2] = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
    out[3] = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
}

opx_pose ingest_sensor_pose(const ingest_frame *frame, const opx_pose *viewpoint, const char **source) {
    const opx_pose identity = OPX_POSE_IDENTITY;
    opx_pose pose = identity;
    *source = "default";
    if (frame->has_sensor_pose) {
        pose = frame->sensor_pose;
        *source = "--sensor-pose";
    } else if (viewpoint != NULL) {
        pose = *viewpoint;
        *source = "VIEWPOINT";
    }
    if (frame->optical_frame) {
        double turned[4];
        multiply(pose.orientation, kOpticalInBody, turned);
        memcpy(pose.orientation, turned, sizeof turned);
    }
    return pose;
}

/* The cloud's points, packed x y z; -1, or the exit code after a message
 * (the reader's own for a file it refuses: exit 3). */
static int read_points(const char *path, opx_point_cloud_info *info, float **xyz) {
    opx_point_cloud *cloud = NULL;
    size_t count = 0;
    opx_status status = opx_point_cloud_read_file(path, &cloud);
    if (status == OPX_OK) status = opx_point_cloud_get_info(cloud, info);
    if (status != OPX_OK) {
        opx_point_cloud_destroy(cloud);
        return cli_library_fail("ingest", status, "reading %s", path);
    }
    if (info->point_count > SIZE_MAX / (3 * sizeof(float)) - 1 ||
        (*xyz = malloc((size_t)info->point_count * 3 * sizeof(float) + 1)) == NULL) {
        opx_point_cloud_destroy(cloud);
        return cli_fail("ingest", CLI_EXIT_INTERNAL, "%s: out of memory for %llu points", path,
                        (unsigned long long)info->point_count);
    }
    status = opx_point_cloud_get_points(cloud, *xyz, (size_t)info->point_count, 0, &count);
    opx_point_cloud_destroy(cloud);
    if (status == OPX_OK) return -1;
    free(*xyz);
    *xyz = NULL;
    return cli_library_fail("ingest", status, "reading the points of %s", path);
}

static const char *encoding_name(int32_t encoding) {
    if (encoding == OPX_CLOUD_ENCODING_ASCII) return "ascii";
    if (encoding == OPX_CLOUD_ENCODING_BINARY_COMPRESSED) return "binary_compressed";
    return "binary";
}

int ingest_cloud_file(const char *path, opx_octree *map, const ingest_frame *frame,
                      const opx_insert_options *insert, ingest_result *result) {
    opx_point_cloud_info info = OPX_POINT_CLOUD_INFO_INIT;
    opx_insert_options options = *insert;
    float *xyz = NULL;
    opx_status status;
    double start;
    int code = read_points(path, &info, &xyz);
    if (code >= 0) return code;
    snprintf(result->format, sizeof result->format, "%s %s", info.format == OPX_CLOUD_FORMAT_PCD ? "pcd" : "ply",
             info.format == OPX_CLOUD_FORMAT_PLY && info.encoding == OPX_CLOUD_ENCODING_BINARY
                 ? "binary_little_endian"
                 : encoding_name(info.encoding));
    result->points = (size_t)info.point_count;
    result->report = (opx_insert_report)OPX_INSERT_REPORT_INIT;
    result->sensor_pose = ingest_sensor_pose(frame, info.has_viewpoint ? &info.viewpoint : NULL,
                                             &result->pose_source);
    options.sensor_pose = result->sensor_pose;
    start = cli_now_ms();
    status = result->points == 0
                 ? OPX_OK
                 : opx_octree_insert_points(map, xyz, result->points, 0, OPX_SCALAR_FLOAT32, &options, &result->report);
    result->insert_ms = cli_now_ms() - start;
    free(xyz);
    if (status == OPX_OK) return -1;
    if (status == OPX_ERROR_INVALID_ARGUMENT && strcmp(result->pose_source, "VIEWPOINT") == 0)
        return cli_fail("ingest", CLI_EXIT_INPUT, "%s: its VIEWPOINT is no pose (%s); give --sensor-pose", path,
                        opx_last_error());
    return cli_library_fail("ingest", status, "inserting %s", path);
}
