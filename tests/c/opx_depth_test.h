/*
 * A tiny depth frame shared by the depth-image tests: 4 x 3 pixels, five
 * of them without a return, seen by a pinhole camera whose points fall on
 * multiples of RES (so from a sensor at (C0, C0, C0) every endpoint is a
 * cell centre), and the points it back-projects to, computed by hand.
 */
#ifndef OPX_DEPTH_TEST_H
#define OPX_DEPTH_TEST_H

#include "opx_test.h"

#define TINY_W 4
#define TINY_H 3
#define TINY_VALID 7
#define TINY_NO_RETURN 5

/* fx = 2, fy = 4, cx = 1.5, cy = 1: x = (u - 1.5) * z / 2, y = (v - 1) * z / 4. */
static inline opx_camera_intrinsics tiny_camera(void) {
    opx_camera_intrinsics k = OPX_CAMERA_INTRINSICS_INIT;
    k.fx = 2.0;
    k.fy = 4.0;
    k.cx = 1.5;
    k.cy = 1.0;
    return k;
}

/* Millimetres, row after row; 0 is no return. */
static const uint16_t TINY_MM[TINY_H][TINY_W] = {
    {2000, 0, 2000, 1000},
    {2000, 2000, 0, 3000},
    {0, 2000, 0, 0},
};

/* The same frame in metres, each kind of missing return once. */
static inline void tiny_metres(float out[TINY_H][TINY_W]) {
    for (int v = 0; v < TINY_H; ++v)
        for (int u = 0; u < TINY_W; ++u) out[v][u] = (float)TINY_MM[v][u] / 1000.0f;
    out[0][1] = NAN;
    out[1][2] = INFINITY;
    out[2][0] = 0.0f;
    out[2][2] = -1.0f;
    out[2][3] = -INFINITY;
}

/* The optical-frame points of the pixels with a return, in row order. */
static const double TINY_POINTS[TINY_VALID][3] = {
    {-1.5, -0.5, 2.0},  /* (u 0, v 0), 2 m */
    {0.5, -0.5, 2.0},   /* (2, 0), 2 m */
    {0.75, -0.25, 1.0}, /* (3, 0), 1 m */
    {-1.5, 0.0, 2.0},   /* (0, 1), 2 m */
    {-0.5, 0.0, 2.0},   /* (1, 1), 2 m */
    {2.25, 0.0, 3.0},   /* (3, 1), 3 m */
    {-0.5, 0.5, 2.0},   /* (1, 2), 2 m */
};

static inline opx_depth_image tiny_image_mm(void) {
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    image.data = TINY_MM;
    image.width = TINY_W;
    image.height = TINY_H;
    image.depth_scale = 1000.0;
    return image;
}

static inline opx_depth_image float_image(const float *metres, size_t width, size_t height) {
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    image.scalar_type = OPX_SCALAR_FLOAT32;
    image.data = metres;
    image.width = width;
    image.height = height;
    return image;
}

static inline opx_insert_report insert_depth(opx_octree *tree, const opx_depth_image *image,
                                             const opx_camera_intrinsics *camera,
                                             const opx_insert_options *options) {
    opx_insert_report report = OPX_INSERT_REPORT_INIT;
    assert_ok(opx_octree_insert_depth_image(tree, image, camera, options, &report));
    return report;
}

/* Every pixel is counted once. */
static inline void assert_pixels_add_up(const opx_insert_report *r, size_t pixels) {
    assert_int_equal(r->points_used + r->points_nonfinite + r->points_out_of_range +
                         r->points_outside_map + r->pixels_no_return,
                     pixels);
}

/* Both maps have the same leaves, probabilities included. */
static inline void assert_same_maps(const opx_octree *a, const opx_octree *b) {
    map_snapshot sa = take_snapshot(a), sb = take_snapshot(b);
    assert_same_stats(&sa.stats, &sb.stats);
    assert_same_leaves(sa.leaves, sa.count, sb.leaves, sb.count);
    free(sa.leaves);
    free(sb.leaves);
}

#endif /* OPX_DEPTH_TEST_H */
