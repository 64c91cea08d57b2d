/* The demo's exact depth renderer: see depth_render.h. */
#include "depth_render.h"

#include "shape_mesh.h"

#include <math.h>
#include <stdlib.h>

/* Nearer than this to the camera's plane a vertex does not project; a
 * triangle reaching there is tested on every pixel. */
#define NEAR_Z 1e-9

typedef struct camera_triangle {
    double a[3], e1[3], e2[3]; /* vertex a and the edges a->b, a->c, optical frame */
} camera_triangle;

static void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

static double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* A map-frame vertex in the optical frame: R^T (p - t). */
static void to_camera(const depth_camera *camera, const float *vertex, double out[3]) {
    const double *q = camera->pose.orientation;
    const double inverse[4] = {-q[0], -q[1], -q[2], q[3]};
    const double d[3] = {vertex[0] - camera->pose.position[0], vertex[1] - camera->pose.position[1],
                         vertex[2] - camera->pose.position[2]};
    pose_rotate(inverse, d, out);
}

/* Moller-Trumbore from the camera's origin along dir (dir z = 1, so the
 * ray parameter is the optical-axis depth); INFINITY on a miss.  The
 * barycentric tests are closed: an edge or a vertex is a hit. */
static double ray_hit(const camera_triangle *t, const double dir[3]) {
    double p[3], q[3], det, inverse, s[3], u, v, depth;
    cross(dir, t->e2, p);
    det = dot(t->e1, p);
    if (det == 0.0) return INFINITY; /* the ray runs in the triangle's plane */
    inverse = 1.0 / det;
    s[0] = -t->a[0];
    s[1] = -t->a[1];
    s[2] = -t->a[2];
    u = dot(s, p) * inverse;
    if (u < 0.0 || u > 1.0) return INFINITY;
    cross(s, t->e1, q);
    v = dot(dir, q) * inverse;
    if (v < 0.0 || u + v > 1.0) return INFINITY;
    depth = dot(t->e2, q) * inverse;
    return depth > 0.0 ? depth : INFINITY;
}

/* The pixels whose rays can meet the triangle (the projection's bounding
 * box, a pixel wider each way); 0 when none can. */
static int pixel_box(const depth_camera *camera, const double v[3][3], long box[4]) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    int k, behind = 0;
    for (k = 0; k < 3; ++k) {
        if (v[k][2] <= NEAR_Z) {
            ++behind;
            continue;
        }
        lo[0] = fmin(lo[0], camera->fx * v[k][0] / v[k][2] + camera->cx);
        hi[0] = fmax(hi[0], camera->fx * v[k][0] / v[k][2] + camera->cx);
        lo[1] = fmin(lo[1], camera->fy * v[k][1] / v[k][2] + camera->cy);
        hi[1] = fmax(hi[1], camera->fy * v[k][1] / v[k][2] + camera->cy);
    }
    if (behind == 3) return 0;
    if (behind > 0) { /* crosses the camera's plane: its image is unbounded */
        lo[0] = lo[1] = 0.0;
        hi[0] = camera->width;
        hi[1] = camera->height;
    }
    box[0] = (long)fmax(floor(lo[0]) - 1.0, 0.0);
    box[1] = (long)fmax(floor(lo[1]) - 1.0, 0.0);
    box[2] = (long)fmin(ceil(hi[0]) + 1.0, (double)camera->width - 1.0);
    box[3] = (long)fmin(ceil(hi[1]) + 1.0, (double)camera->height - 1.0);
    return box[0] <= box[2] && box[1] <= box[3];
}

static void render_triangle(const depth_camera *camera, const double v[3][3], double *depth) {
    camera_triangle t;
    long box[4], u, row;
    int axis;
    if (!pixel_box(camera, v, box)) return;
    for (axis = 0; axis < 3; ++axis) {
        t.a[axis] = v[0][axis];
        t.e1[axis] = v[1][axis] - v[0][axis];
        t.e2[axis] = v[2][axis] - v[0][axis];
    }
    for (row = box[1]; row <= box[3]; ++row)
        for (u = box[0]; u <= box[2]; ++u) {
            const double dir[3] = {((double)u - camera->cx) / camera->fx, ((double)row - camera->cy) / camera->fy, 1.0};
            const double d = ray_hit(&t, dir);
            double *pixel = &depth[(size_t)row * camera->width + (size_t)u];
            if (d < *pixel) *pixel = d;
        }
}

int depth_render(const mesh_out *mesh, const depth_camera *camera, double *depth) {
    const size_t pixels = (size_t)camera->width * camera->height;
    double *vertices = malloc((mesh->vertex_count > 0 ? mesh->vertex_count : 1) * 3 * sizeof *vertices);
    size_t i, f;
    if (vertices == NULL) return -1;
    for (i = 0; i < pixels; ++i) depth[i] = INFINITY;
    for (i = 0; i < mesh->vertex_count; ++i) to_camera(camera, &mesh->vertices[3 * i], &vertices[3 * i]);
    for (f = 0; f < mesh->face_count; ++f) {
        const uint32_t *face = &mesh->faces[4 * f];
        const int corners = face[3] == UINT32_MAX ? 3 : 4;
        int k, fan;
        for (fan = 0; fan + 2 < corners; ++fan) { /* a quad: two triangles */
            const uint32_t index[3] = {face[0], face[fan + 1], face[fan + 2]};
            double v[3][3];
            for (k = 0; k < 3; ++k) {
                v[k][0] = vertices[3 * index[k]];
                v[k][1] = vertices[3 * index[k] + 1];
                v[k][2] = vertices[3 * index[k] + 2];
            }
            render_triangle(camera, (const double(*)[3])v, depth);
        }
    }
    free(vertices);
    return 0;
}

size_t depth_composite(float *xyz, const double *depth, const depth_camera *camera) {
    size_t replaced = 0, u, v;
    for (v = 0; v < camera->height; ++v)
        for (u = 0; u < camera->width; ++u) {
            const size_t i = v * camera->width + u;
            float *p = &xyz[3 * i];
            const int has_return = isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]);
            const double d = depth[i];
            if (!isfinite(d) || (has_return && (double)p[2] <= d)) continue;
            p[0] = (float)(((double)u - camera->cx) / camera->fx * d);
            p[1] = (float)(((double)v - camera->cy) / camera->fy * d);
            p[2] = (float)d;
            ++replaced;
        }
    return replaced;
}
