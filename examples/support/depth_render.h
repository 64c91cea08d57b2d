/*
 * An exact depth renderer for the demo: a pinhole camera (no distortion)
 * looks at map-frame triangles, and each pixel's depth is where the ray
 * through that pixel meets the nearest triangle, computed per pixel
 * (Moller-Trumbore), not interpolated.  The camera's frame is the optical
 * frame (z forward, x right, y down); the pixel in column u and row v looks
 * along ((u - cx) / fx, (v - cy) / fy, 1), the ray octree.h back-projects a
 * depth image along, so a rendered depth and a depth frame's pixel name the
 * same ray.
 */
#ifndef OPX_EXAMPLES_DEPTH_RENDER_H
#define OPX_EXAMPLES_DEPTH_RENDER_H

#include "mesh_out.h"

#include <octoprox/octoprox.h>

typedef struct depth_camera {
    opx_pose pose;           /* the optical frame in the map frame */
    double fx, fy, cx, cy;   /* pixels */
    uint32_t width, height;  /* columns, rows */
} depth_camera;

/* depth[v * width + u]: the optical-axis depth (metres) of the nearest
 * triangle (or quad, as two triangles) of `mesh` on pixel (u, v)'s ray in
 * front of the camera, INFINITY where the ray meets none.  A ray through
 * a triangle's edge or vertex hits it.  0, or -1 when out of memory. */
int depth_render(const mesh_out *mesh, const depth_camera *camera, double *depth);

/* Composites a rendering into an organized cloud of the same camera
 * (xyz: width * height points, x y z in the optical frame, NaN where the
 * pixel has no return): where the rendered surface is nearer along the
 * pixel's ray than the cloud's point, or the pixel has no return, the
 * pixel takes the rendered point.  Returns the pixels replaced. */
size_t depth_composite(float *xyz, const double *depth, const depth_camera *camera);

#endif /* OPX_EXAMPLES_DEPTH_RENDER_H */
