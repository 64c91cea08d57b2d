/*
 * OctoProx: collision and distance queries between robots and live
 * point-cloud occupancy octrees.  Common definitions of the C ABI.
 *
 * Conventions used by every header of this library:
 *  - Units are SI: metres, radians.  Frames are right-handed.
 *  - A pose is a position and a unit quaternion in ROS order:
 *    x y z qx qy qz qw (see opx_pose).
 *  - Every fallible function returns opx_status: 0 on success, a negative
 *    code on error.  opx_last_error() then tells which function and which
 *    argument failed.  On error nothing an object already held is lost.
 *  - Every options/request/result struct starts with `struct_size`; fill it
 *    with its OPX_X_INIT macro or opx_x_init(ptr, sizeof *ptr).  Fields are
 *    only ever appended, so old callers keep working: the library reads and
 *    writes no more than struct_size bytes.  A struct_size below 4 (0: an
 *    uninitialised struct) gives OPX_ERROR_VERSION; opx_x_init sets
 *    struct_size to min(size, the library's size of the struct).
 *  - Arrays are (pointer, count, stride in bytes); a stride of 0 means packed.
 *  - The library never keeps a caller's pointer after a call returns.
 *  - Functions taking a `const` handle may run concurrently on the same
 *    object; the others need exclusive access to it.
 *  - Names: opx_<object>_<verb>.  An accessor that reads a value out of an
 *    object is opx_<object>_get_<thing> (opx_linkset_get_link_count,
 *    opx_octree_get_stats, opx_query_get_contact), its setter
 *    opx_<object>_set_<thing>, a lookup by name opx_<object>_find_<thing>.
 */
#ifndef OCTOPROX_COMMON_H
#define OCTOPROX_COMMON_H

#include <stddef.h>
#include <stdint.h>

#define OPX_VERSION_MAJOR 0
#define OPX_VERSION_MINOR 1
#define OPX_VERSION_PATCH 0
/* The SONAME names the ABI: liboctoprox.so.0.MINOR while MAJOR is 0 (a
 * minor release may change the ABI), liboctoprox.so.MAJOR from 1.0 on. */
/** One number that grows with every release: major*10000 + minor*100 + patch. */
#define OPX_VERSION_NUMBER \
    (OPX_VERSION_MAJOR * 10000 + OPX_VERSION_MINOR * 100 + OPX_VERSION_PATCH)

#if defined(OPX_STATIC)
#define OPX_API
#elif defined(_WIN32)
#if defined(OPX_BUILDING_LIBRARY)
#define OPX_API __declspec(dllexport)
#else
#define OPX_API __declspec(dllimport)
#endif
#else
#define OPX_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

/** Status codes.  Never renumbered; new codes are only appended. */
typedef int32_t opx_status;
#define OPX_OK 0
#define OPX_ERROR_INVALID_ARGUMENT (-1) /**< NULL, NaN, out of range, bad stride... */
#define OPX_ERROR_OUT_OF_MEMORY (-2)
#define OPX_ERROR_VERSION (-3)          /**< struct_size 0 or unknown version */
#define OPX_ERROR_BUFFER_TOO_SMALL (-4) /**< the needed size is reported */
#define OPX_ERROR_UNSUPPORTED (-5)      /**< valid, but not handled (yet) */
#define OPX_ERROR_IO (-6)               /**< a file could not be read or written */
#define OPX_ERROR_CORRUPT (-7)          /**< malformed or truncated input data */
#define OPX_ERROR_INTERNAL (-8)         /**< a bug: please report it */

/** The name of a status code ("OPX_ERROR_IO"), or "OPX_UNKNOWN_STATUS". */
OPX_API const char *opx_status_name(opx_status status);

/**
 * The message of the last failed call on this thread, naming the function
 * and the argument, e.g. "opx_octree_insert_points: stride 4 is smaller than
 * one point (12 bytes)".  Never NULL; "" when no call failed yet.  Valid
 * until the next failing call on the same thread.
 */
OPX_API const char *opx_last_error(void);

/** The run-time version, "0.1.0"; compare with OPX_VERSION_* at build time. */
OPX_API const char *opx_version(void);
/** The run-time OPX_VERSION_NUMBER. */
OPX_API uint32_t opx_version_number(void);

/**
 * A rigid transform: the pose of a child frame in a parent frame.
 * position: metres.  orientation: unit quaternion x, y, z, w (ROS order);
 * it is normalised by the library; a zero or non-finite quaternion is an
 * invalid argument.
 */
typedef struct opx_pose {
    double position[3];
    double orientation[4];
} opx_pose;
#define OPX_POSE_IDENTITY {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0, 1.0}}

/* Scalar types of point arrays and depth images. */
#define OPX_SCALAR_FLOAT32 1
#define OPX_SCALAR_FLOAT64 2
#define OPX_SCALAR_UINT16 3 /**< depth images only */

#ifdef __cplusplus
}
#endif

#endif /* OCTOPROX_COMMON_H */
