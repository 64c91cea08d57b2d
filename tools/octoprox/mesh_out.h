/*
 * A coloured, grouped polygon soup written as Wavefront OBJ (with an MTL
 * file of one material per group) or as binary little-endian PLY (vertex
 * colours from the group).  Map frame, metres.
 */
#ifndef OPX_TOOLS_MESH_OUT_H
#define OPX_TOOLS_MESH_OUT_H

#include <stddef.h>
#include <stdint.h>

typedef struct mesh_group {
    char name[128];          /* OBJ group and material name */
    unsigned char rgb[3];
} mesh_group;

typedef struct mesh_out {
    float *vertices;          /* 3 per vertex */
    uint32_t *vertex_group;
    size_t vertex_count, vertex_capacity;
    uint32_t *faces;          /* 4 indices per face; the 4th UINT32_MAX for a triangle */
    uint32_t *face_group;
    size_t face_count, face_capacity;
    mesh_group *groups;
    size_t group_count, group_capacity;
    int failed;               /* an allocation failed; everything after is dropped */
} mesh_out;

void mesh_init(mesh_out *m);
void mesh_free(mesh_out *m);

/* Adds a group; returns its index.  Names are sanitised for OBJ. */
uint32_t mesh_add_group(mesh_out *m, const char *name, unsigned char r, unsigned char g, unsigned char b);
uint32_t mesh_add_vertex(mesh_out *m, uint32_t group, const double xyz[3]);
void mesh_add_triangle(mesh_out *m, uint32_t group, uint32_t a, uint32_t b, uint32_t c);
/* An axis-aligned cube: 8 vertices, 6 quads facing out. */
void mesh_add_cube(mesh_out *m, uint32_t group, const double center[3], double size);

/* 0 on success; -1 when a file cannot be written (errno tells why). */
int mesh_write_obj(const mesh_out *m, const char *path);
int mesh_write_ply(const mesh_out *m, const char *path);

#endif /* OPX_TOOLS_MESH_OUT_H */
