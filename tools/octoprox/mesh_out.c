/* Grouped polygon soups as OBJ and PLY: see mesh_out.h. */
#include "mesh_out.h"

#include "atomic_file.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void mesh_init(mesh_out *m) { memset(m, 0, sizeof *m); }

void mesh_free(mesh_out *m) {
    free(m->vertices);
    free(m->vertex_group);
    free(m->faces);
    free(m->face_group);
    free(m->groups);
    mesh_init(m);
}

/* Grows an array to hold `needed` items; 0 on success. */
static int grow(void **items, size_t *capacity, size_t needed, size_t item_size) {
    size_t n = *capacity ? *capacity : 64;
    void *bigger;
    if (needed <= *capacity) return 0;
    while (n < needed) n *= 2;
    bigger = realloc(*items, n * item_size);
    if (bigger == NULL) return -1;
    *items = bigger;
    *capacity = n;
    return 0;
}

uint32_t mesh_add_group(mesh_out *m, const char *name, unsigned char r, unsigned char g, unsigned char b) {
    mesh_group *group;
    char *c;
    if (m->failed || grow((void **)&m->groups, &m->group_capacity, m->group_count + 1, sizeof *m->groups)) {
        m->failed = 1;
        return 0;
    }
    group = &m->groups[m->group_count];
    snprintf(group->name, sizeof group->name, "%s", name);
    for (c = group->name; *c; ++c)
        if (*c == ' ' || *c == '\t' || *c == '#') *c = '_';
    group->rgb[0] = r;
    group->rgb[1] = g;
    group->rgb[2] = b;
    return (uint32_t)m->group_count++;
}

uint32_t mesh_add_vertex(mesh_out *m, uint32_t group, const double xyz[3]) {
    const size_t need = m->vertex_count + 1;
    size_t group_capacity = m->vertex_capacity;
    if (m->failed || grow((void **)&m->vertex_group, &group_capacity, need, sizeof(uint32_t)) ||
        grow((void **)&m->vertices, &m->vertex_capacity, need, 3 * sizeof(float))) {
        m->failed = 1;
        return 0;
    }
    m->vertices[3 * m->vertex_count] = (float)xyz[0];
    m->vertices[3 * m->vertex_count + 1] = (float)xyz[1];
    m->vertices[3 * m->vertex_count + 2] = (float)xyz[2];
    m->vertex_group[m->vertex_count] = group;
    return (uint32_t)m->vertex_count++;
}

static void add_face(mesh_out *m, uint32_t group, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
    const size_t need = m->face_count + 1;
    size_t group_capacity = m->face_capacity;
    if (m->failed || grow((void **)&m->face_group, &group_capacity, need, sizeof(uint32_t)) ||
        grow((void **)&m->faces, &m->face_capacity, need, 4 * sizeof(uint32_t))) {
        m->failed = 1;
        return;
    }
    m->faces[4 * m->face_count] = a;
    m->faces[4 * m->face_count + 1] = b;
    m->faces[4 * m->face_count + 2] = c;
    m->faces[4 * m->face_count + 3] = d;
    m->face_group[m->face_count++] = group;
}

void mesh_add_triangle(mesh_out *m, uint32_t group, uint32_t a, uint32_t b, uint32_t c) {
    add_face(m, group, a, b, c, UINT32_MAX);
}

void mesh_add_cube(mesh_out *m, uint32_t group, const double center[3], double size) {
    /* Corner i has x = bit 0, y = bit 1, z = bit 2; quads wind outwards. */
    static const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    const double h = 0.5 * size;
    uint32_t first = 0, i;
    int q;
    for (i = 0; i < 8; ++i) {
        const double corner[3] = {center[0] + ((i & 1) ? h : -h), center[1] + ((i & 2) ? h : -h),
                                  center[2] + ((i & 4) ? h : -h)};
        const uint32_t index = mesh_add_vertex(m, group, corner);
        if (i == 0) first = index;
    }
    for (q = 0; q < 6; ++q)
        add_face(m, group, first + quads[q][0], first + quads[q][1], first + quads[q][2], first + quads[q][3]);
}

/* Face indices ordered by group (a counting sort), for OBJ's groups. */
static size_t *faces_by_group(const mesh_out *m, size_t *starts) {
    size_t *order = malloc((m->face_count + 1) * sizeof *order), g, f;
    if (order == NULL) return NULL;
    for (g = 0; g <= m->group_count; ++g) starts[g] = 0;
    for (f = 0; f < m->face_count; ++f) ++starts[m->face_group[f] + 1];
    for (g = 0; g < m->group_count; ++g) starts[g + 1] += starts[g];
    {
        size_t *next = malloc((m->group_count + 1) * sizeof *next);
        if (next == NULL) {
            free(order);
            return NULL;
        }
        memcpy(next, starts, (m->group_count + 1) * sizeof *next);
        for (f = 0; f < m->face_count; ++f) order[next[m->face_group[f]]++] = f;
        free(next);
    }
    return order;
}

static void write_mtl(const mesh_out *m, FILE *file) {
    size_t g;
    for (g = 0; g < m->group_count; ++g)
        fprintf(file, "newmtl %s\nKd %.3f %.3f %.3f\n\n", m->groups[g].name, m->groups[g].rgb[0] / 255.0,
                m->groups[g].rgb[1] / 255.0, m->groups[g].rgb[2] / 255.0);
}

static void write_obj_faces(FILE *file, const mesh_out *m, const size_t *order, const size_t *starts) {
    size_t g, k;
    for (g = 0; g < m->group_count; ++g) {
        if (starts[g] == starts[g + 1]) continue;
        fprintf(file, "g %s\nusemtl %s\n", m->groups[g].name, m->groups[g].name);
        for (k = starts[g]; k < starts[g + 1]; ++k) {
            const uint32_t *f = &m->faces[4 * order[k]];
            if (f[3] == UINT32_MAX) fprintf(file, "f %u %u %u\n", f[0] + 1, f[1] + 1, f[2] + 1);
            else fprintf(file, "f %u %u %u %u\n", f[0] + 1, f[1] + 1, f[2] + 1, f[3] + 1);
        }
    }
}

static void write_obj(const mesh_out *m, FILE *file, const char *mtl_name, const size_t *order,
                      const size_t *starts) {
    size_t v;
    fprintf(file, "# octoprox export: %zu vertices, %zu faces, map frame, metres\nmtllib %s\n", m->vertex_count,
            m->face_count, mtl_name);
    for (v = 0; v < m->vertex_count; ++v)
        fprintf(file, "v %.6f %.6f %.6f\n", m->vertices[3 * v], m->vertices[3 * v + 1], m->vertices[3 * v + 2]);
    write_obj_faces(file, m, order, starts);
}

/* Both files are written and synced before either replaces its target,
 * so a failure leaves the previous OBJ and MTL as they were. */
static int write_obj_and_mtl(const mesh_out *m, const char *path, const char *mtl, const size_t *order,
                             const size_t *starts) {
    const char *slash = strrchr(path, '/');
    atomic_file obj_file, mtl_file;
    if (atomic_file_open(&mtl_file, mtl) != 0) return -1;
    write_mtl(m, mtl_file.stream);
    if (atomic_file_finish(&mtl_file) != 0) return -1;
    if (atomic_file_open(&obj_file, path) != 0) {
        atomic_file_discard(&mtl_file);
        return -1;
    }
    write_obj(m, obj_file.stream, slash ? mtl + (slash - path) + 1 : mtl, order, starts);
    if (atomic_file_finish(&obj_file) != 0) {
        atomic_file_discard(&mtl_file);
        return -1;
    }
    if (atomic_file_publish(&mtl_file) != 0) {
        atomic_file_discard(&obj_file);
        return -1;
    }
    return atomic_file_publish(&obj_file);
}

int mesh_write_obj(const mesh_out *m, const char *path) {
    char mtl[4096];
    size_t *starts = malloc((m->group_count + 1) * sizeof *starts), *order;
    int status;
    if (starts == NULL || (order = faces_by_group(m, starts)) == NULL) {
        free(starts);
        return -1;
    }
    snprintf(mtl, sizeof mtl, "%s.mtl", path);
    status = write_obj_and_mtl(m, path, mtl, order, starts);
    free(order);
    free(starts);
    return status;
}

int mesh_write_ply(const mesh_out *m, const char *path) {
    atomic_file output;
    FILE *file;
    size_t v, f;
    if (atomic_file_open(&output, path) != 0) return -1;
    file = output.stream;
    fprintf(file, "ply\nformat binary_little_endian 1.0\ncomment octoprox export, map frame, metres\n"
                  "element vertex %zu\nproperty float x\nproperty float y\nproperty float z\n"
                  "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                  "element face %zu\nproperty list uchar int vertex_indices\nend_header\n",
            m->vertex_count, m->face_count);
    for (v = 0; v < m->vertex_count; ++v) {
        fwrite(&m->vertices[3 * v], sizeof(float), 3, file); /* x86/ARM hosts are little-endian */
        fwrite(m->groups[m->vertex_group[v]].rgb, 1, 3, file);
    }
    for (f = 0; f < m->face_count; ++f) {
        const uint32_t *face = &m->faces[4 * f];
        const unsigned char n = face[3] == UINT32_MAX ? 3 : 4;
        fwrite(&n, 1, 1, file);
        fwrite(face, sizeof(uint32_t), n, file);
    }
    return atomic_file_commit(&output);
}
