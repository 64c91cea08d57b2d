/*
 * What the demo picture's drawing files share: the frame being drawn, the
 * map-to-pixel projection and the palette (demo_picture.c), and the robot
 * drawing (picture_robot.c: the still body, the arm at a few waypoints, the
 * tool's path, the known objects).
 */
#ifndef OPX_EXAMPLES_PICTURE_FRAME_H
#define OPX_EXAMPLES_PICTURE_FRAME_H

#include "canvas.h"
#include "demo_picture.h"

typedef struct picture_frame {
    canvas c;
    const picture_view *view;
    int plot_w, plot_h;
} picture_frame;

/* Map point -> pixel (x right along u, y down along -v). */
void picture_to_pixel(const picture_frame *f, const double p[3], double out[2]);

extern const colour kOccupied, kFree, kUnknown, kUncertain, kCollision, kCost, kText, kSensor;
extern const colour kBody, kBodyEdge, kArmColours[PICTURE_MAX_ARMS];
extern const colour kKnown;

/* Fill opacities: the still body solid enough to read over any cell
 * colour, the arms light enough that overlapping poses stay apart. */
#define BODY_ALPHA 0.6
#define ARM_ALPHA 0.2

/* An outline pixel at (x, y): the edge colour, in red dashes where the pose
 * collides. */
colour picture_outline_colour(colour edge, int collides, int x, int y);

/* The body, then the arms: each pixel tinted once, by the latest waypoint
 * covering it, under every outline. */
void picture_draw_robot(picture_frame *f, const picture_input *in);
/* The known objects' silhouettes: diagonal hatching over a light tint,
 * outlined; and a red ring at each point where the robot touches one. */
void picture_draw_known(picture_frame *f, const picture_input *in);
void picture_draw_object_contacts(picture_frame *f, const picture_input *in);
/* A legend swatch of the known objects' hatching at (x, y), 22 x 14. */
void picture_known_swatch(picture_frame *f, int x, int y);
/* The tool's path: a line through a dot a waypoint, red where it collides,
 * and a disc with the waypoint's number where an arm is drawn. */
void picture_draw_tool_path(picture_frame *f, const picture_input *in);

#endif /* OPX_EXAMPLES_PICTURE_FRAME_H */
