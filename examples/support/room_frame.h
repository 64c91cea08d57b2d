/*
 * A synthetic depth-camera frame of a furnished room, for the examples and
 * the benchmark when no real data is at hand.  C99, no dependencies.
 *
 * The camera is a Kinect-like pinhole (640 x 480, fx = fy = 525,
 * cx = 319.5, cy = 239.5) looking into a 6 x 5 x 2.8 m room from 1.4 m
 * height, pitched 10 degrees down.  The room (map frame, z up, metres):
 *   walls        x in [-1, 5], y in [-2.5, 2.5], floor z = 0, ceiling z = 2.8
 *   table        x in [1.2, 2.2], y in [-0.6, 0.6], top at z = 0.73, four legs
 *   two boxes    on the floor, right and left of the table's far end
 *   a cylinder   (a bin) of radius 0.2 m, 0.9 m high, left of the table
 *   a window     in the far wall (x = 5) that returns nothing (NaN pixels)
 * Each pixel is ray-cast analytically; the depth gets ~2 mm of
 * Gaussian-like noise from a seeded generator, so a frame is reproducible.
 */
#ifndef OPX_EXAMPLES_ROOM_FRAME_H
#define OPX_EXAMPLES_ROOM_FRAME_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define ROOM_FRAME_WIDTH 640u
#define ROOM_FRAME_HEIGHT 480u
/* Pixels farther than this return nothing, like a real depth camera. */
#define ROOM_FRAME_MAX_DEPTH 8.0

typedef struct room_frame {
    uint32_t width, height;
    /* width * height points, row by row, packed x y z in the camera OPTICAL
     * frame (x right, y down, z forward), metres; NaN where no return. */
    float *xyz;
    size_t count;
    size_t finite_count;
    /* The suggested pose of the optical frame in the map frame (z up):
     * position in metres, quaternion x y z w (ROS order). */
    double sensor_position[3];
    double sensor_orientation[4];
} room_frame;

/* Points of interest in the map frame, for probing a map of the room. */
typedef struct room_landmarks {
    double table_top[3];    /* on the table's top surface */
    double free_air[3];     /* 1 m in front of the camera, on its axis */
    double behind_wall[3];  /* 1 m behind the far wall: never observed */
    double behind_box[3];   /* on the floor behind the left box: hidden */
} room_landmarks;

/* Renders the frame; seed selects the noise.  Returns 0, or -1 when out of
 * memory (*out is then empty).  Free with room_frame_free. */
int room_frame_generate(uint32_t seed, room_frame *out);
void room_frame_free(room_frame *frame);

void room_frame_landmarks(room_landmarks *out);

#ifdef __cplusplus
}
#endif

#endif /* OPX_EXAMPLES_ROOM_FRAME_H */
