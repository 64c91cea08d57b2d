/* Robot shapes as triangles: see shape_mesh.h. */
#include "shape_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define SLICES 16
#define STACKS 8
#define MAX_HULL_VERTICES 64

static void normalise(const double q[4], double out[4]) {
    const double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    int i;
    for (i = 0; i < 4; ++i) out[i] = n > 0 ? q[i] / n : (i == 3 ? 1.0 : 0.0);
}

void pose_rotate(const double q[4], const double v[3], double out[3]) {
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double cx = y * v[2] - z * v[1], cy = z * v[0] - x * v[2], cz = x * v[1] - y * v[0];
    out[0] = v[0] + 2.0 * (w * cx + y * cz - z * cy);
    out[1] = v[1] + 2.0 * (w * cy + z * cx - x * cz);
    out[2] = v[2] + 2.0 * (w * cz + x * cy - y * cx);
}

void pose_apply(const opx_pose *pose, const double in[3], double out[3]) {
    double q[4], r[3];
    normalise(pose->orientation, q);
    pose_rotate(q, in, r);
    out[0] = r[0] + pose->position[0];
    out[1] = r[1] + pose->position[1];
    out[2] = r[2] + pose->position[2];
}

void pose_compose(const opx_pose *a, const opx_pose *b, opx_pose *out) {
    double qa[4], qb[4];
    opx_pose result;
    normalise(a->orientation, qa);
    normalise(b->orientation, qb);
    pose_apply(a, b->position, result.position);
    result.orientation[0] = qa[3] * qb[0] + qa[0] * qb[3] + qa[1] * qb[2] - qa[2] * qb[1];
    result.orientation[1] = qa[3] * qb[1] - qa[0] * qb[2] + qa[1] * qb[3] + qa[2] * qb[0];
    result.orientation[2] = qa[3] * qb[2] + qa[0] * qb[1] - qa[1] * qb[0] + qa[2] * qb[3];
    result.orientation[3] = qa[3] * qb[3] - qa[0] * qb[0] - qa[1] * qb[1] - qa[2] * qb[2];
    *out = result;
}

static uint32_t add_point(mesh_out *m, uint32_t group, const opx_pose *pose, double x, double y, double z) {
    const double local[3] = {x, y, z};
    double world[3];
    pose_apply(pose, local, world);
    return mesh_add_vertex(m, group, world);
}

static void add_box(mesh_out *m, uint32_t group, const opx_pose *pose, const double size[3]) {
    static const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    uint32_t first = 0, i;
    int q;
    for (i = 0; i < 8; ++i) {
        const uint32_t v = add_point(m, group, pose, (i & 1 ? 0.5 : -0.5) * size[0], (i & 2 ? 0.5 : -0.5) * size[1],
                                     (i & 4 ? 0.5 : -0.5) * size[2]);
        if (i == 0) first = v;
    }
    for (q = 0; q < 6; ++q) {
        mesh_add_triangle(m, group, first + quads[q][0], first + quads[q][1], first + quads[q][2]);
        mesh_add_triangle(m, group, first + quads[q][0], first + quads[q][2], first + quads[q][3]);
    }
}

/* A UV sphere of `radius`; its two halves pulled apart by half_length
 * along z make a capsule. */
static void add_rounded(mesh_out *m, uint32_t group, const opx_pose *pose, double radius, double half_length) {
    uint32_t first = 0;
    int i, j;
    for (i = 0; i <= STACKS; ++i) {
        const double polar = PI * i / STACKS, z = radius * cos(polar);
        const double shift = i < STACKS / 2 ? half_length : (i > STACKS / 2 ? -half_length : 0.0);
        for (j = 0; j < SLICES; ++j) {
            const double a = 2.0 * PI * j / SLICES;
            const uint32_t v = add_point(m, group, pose, radius * sin(polar) * cos(a), radius * sin(polar) * sin(a),
                                         z + shift);
            if (i == 0 && j == 0) first = v;
        }
    }
    if (half_length > 0.0) { /* the capsule's cylinder: the equator ring split in two */
        uint32_t ring_top = 0;
        for (j = 0; j < SLICES; ++j) {
            const double a = 2.0 * PI * j / SLICES;
            const uint32_t v = add_point(m, group, pose, radius * cos(a), radius * sin(a), half_length);
            if (j == 0) ring_top = v;
        }
        for (j = 0; j < SLICES; ++j) {
            const uint32_t e = first + (uint32_t)(STACKS / 2 * SLICES), n = (uint32_t)((j + 1) % SLICES);
            mesh_add_triangle(m, group, ring_top + j, e + j, e + n);
            mesh_add_triangle(m, group, ring_top + j, e + n, ring_top + n);
        }
    }
    for (i = 0; i < STACKS; ++i) {
        for (j = 0; j < SLICES; ++j) {
            const uint32_t a = first + (uint32_t)(i * SLICES + j), b = first + (uint32_t)(i * SLICES + (j + 1) % SLICES);
            mesh_add_triangle(m, group, a, a + SLICES, b + SLICES);
            mesh_add_triangle(m, group, a, b + SLICES, b);
        }
    }
}

static void add_cylinder(mesh_out *m, uint32_t group, const opx_pose *pose, double radius, double length) {
    const double h = 0.5 * length;
    const uint32_t top = add_point(m, group, pose, 0, 0, h), bottom = add_point(m, group, pose, 0, 0, -h);
    uint32_t ring = 0;
    int j;
    for (j = 0; j < SLICES; ++j) {
        const double a = 2.0 * PI * j / SLICES;
        const uint32_t v = add_point(m, group, pose, radius * cos(a), radius * sin(a), h);
        add_point(m, group, pose, radius * cos(a), radius * sin(a), -h);
        if (j == 0) ring = v;
    }
    for (j = 0; j < SLICES; ++j) {
        const uint32_t t0 = ring + 2 * j, t1 = ring + 2 * ((j + 1) % SLICES);
        mesh_add_triangle(m, group, top, t0, t1);
        mesh_add_triangle(m, group, bottom, t1 + 1, t0 + 1);
        mesh_add_triangle(m, group, t0, t0 + 1, t1 + 1);
        mesh_add_triangle(m, group, t0, t1 + 1, t1);
    }
}

/* Brute-force hull: the triangles with every vertex on their inner side. */
static void add_hull(mesh_out *m, uint32_t group, const opx_pose *pose, const double *v, size_t n) {
    uint32_t first = 0;
    size_t i, j, k, l;
    for (i = 0; i < n; ++i) {
        const uint32_t index = add_point(m, group, pose, v[3 * i], v[3 * i + 1], v[3 * i + 2]);
        if (i == 0) first = index;
    }
    for (i = 0; i < n; ++i)
        for (j = i + 1; j < n; ++j)
            for (k = j + 1; k < n; ++k) {
                const double *a = v + 3 * i, *b = v + 3 * j, *c = v + 3 * k;
                const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
                const double nrm[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
                int above = 0, below = 0;
                for (l = 0; l < n; ++l) {
                    const double d = nrm[0] * (v[3 * l] - a[0]) + nrm[1] * (v[3 * l + 1] - a[1]) + nrm[2] * (v[3 * l + 2] - a[2]);
                    above += d > 1e-12;
                    below += d < -1e-12;
                }
                if (above == 0 && below > 0) mesh_add_triangle(m, group, first + i, first + j, first + k);
                else if (below == 0 && above > 0) mesh_add_triangle(m, group, first + i, first + k, first + j);
            }
}

static void add_bounding_box(mesh_out *m, uint32_t group, const opx_pose *pose, const double *v, size_t n) {
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, size[3];
    opx_pose centred = *pose;
    size_t i;
    int axis;
    for (i = 0; i < n; ++i)
        for (axis = 0; axis < 3; ++axis) {
            if (v[3 * i + axis] < lo[axis]) lo[axis] = v[3 * i + axis];
            if (v[3 * i + axis] > hi[axis]) hi[axis] = v[3 * i + axis];
        }
    {
        const double mid[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
        pose_apply(pose, mid, centred.position);
    }
    for (axis = 0; axis < 3; ++axis) size[axis] = hi[axis] - lo[axis];
    add_box(m, group, &centred, size);
}

static void add_triangles(mesh_out *m, uint32_t group, const opx_pose *pose, const opx_shape *s) {
    uint32_t first = 0;
    size_t i;
    for (i = 0; i < s->vertex_count; ++i) {
        const uint32_t index = add_point(m, group, pose, s->vertices[3 * i], s->vertices[3 * i + 1], s->vertices[3 * i + 2]);
        if (i == 0) first = index;
    }
    for (i = 0; i < s->triangle_count; ++i)
        mesh_add_triangle(m, group, first + s->indices[3 * i], first + s->indices[3 * i + 1], first + s->indices[3 * i + 2]);
}

void shape_to_mesh(const opx_shape *shape, const opx_pose *link_pose, mesh_out *mesh, uint32_t group) {
    opx_pose pose;
    pose_compose(link_pose, &shape->pose, &pose);
    switch (shape->kind) {
    case OPX_SHAPE_SPHERE: add_rounded(mesh, group, &pose, shape->radius, 0.0); break;
    case OPX_SHAPE_CAPSULE: add_rounded(mesh, group, &pose, shape->radius, 0.5 * shape->length); break;
    case OPX_SHAPE_BOX: add_box(mesh, group, &pose, shape->size); break;
    case OPX_SHAPE_CYLINDER: add_cylinder(mesh, group, &pose, shape->radius, shape->length); break;
    case OPX_SHAPE_CONVEX:
        if (shape->vertex_count <= MAX_HULL_VERTICES) add_hull(mesh, group, &pose, shape->vertices, shape->vertex_count);
        else add_bounding_box(mesh, group, &pose, shape->vertices, shape->vertex_count);
        break;
    case OPX_SHAPE_MESH: add_triangles(mesh, group, &pose, shape); break;
    default: break;
    }
}

int linkset_to_mesh(const opx_linkset *links, mesh_out *mesh, const uint32_t *groups) {
    uint32_t link_count = 0, link, shape_count, s;
    if (opx_linkset_get_link_count(links, &link_count) != OPX_OK) return -1;
    for (link = 0; link < link_count; ++link) {
        opx_pose pose;
        if (groups[link] == UINT32_MAX) continue;
        if (opx_linkset_get_pose(links, link, &pose) != OPX_OK) return -1;
        if (opx_linkset_get_shape_count(links, link, &shape_count) != OPX_OK) return -1;
        for (s = 0; s < shape_count; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            if (opx_linkset_get_shape(links, link, s, &shape) != OPX_OK) return -1;
            shape_to_mesh(&shape, &pose, mesh, groups[link]);
        }
    }
    return mesh->failed ? -1 : 0;
}
