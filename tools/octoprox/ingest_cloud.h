/*
 * Point clouds in `octoprox ingest`: where each input's sensor is, and
 * the insert of one PCD or PLY file read through the library.
 *
 * The sensor pose of an input is --sensor-pose when given, else a PCD's
 * VIEWPOINT line (tx ty tz qw qx qy qz, as PCL's viewer places the cloud),
 * else the map origin.  With --optical-frame that pose is the camera's
 * z-up body frame (x forward, y left, z up) and the input is in the
 * camera's optical frame (z forward, x right, y down), as ROS names them
 * camera_link and camera_optical_frame: the optical frame is the body
 * frame turned by the quaternion (-0.5, 0.5, -0.5, 0.5).
 */
#ifndef OPX_TOOLS_INGEST_CLOUD_H
#define OPX_TOOLS_INGEST_CLOUD_H

#include "ingest_depth.h"

typedef struct ingest_frame {
    opx_pose sensor_pose; /* --sensor-pose */
    int has_sensor_pose;
    int optical_frame;    /* --optical-frame */
} ingest_frame;

/* The pose of the frame an input's points are in, in the map frame, and
 * where it came from ("--sensor-pose", "VIEWPOINT" or "default"); the
 * viewpoint is NULL for inputs without one. */
opx_pose ingest_sensor_pose(const ingest_frame *frame, const opx_pose *viewpoint, const char **source);

/* Reads the cloud at path and inserts it with `insert` (its sensor_pose
 * replaced by the input's): -1 on success, else the exit code after a
 * message. */
int ingest_cloud_file(const char *path, opx_octree *map, const ingest_frame *frame,
                      const opx_insert_options *insert, ingest_result *result);

#endif /* OPX_TOOLS_INGEST_CLOUD_H */
