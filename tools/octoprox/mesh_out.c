/* Grouped polygon soups as OBJ and PLY: see mesh_out.h. */
#include "mesh_out.h"

#include <errno.h>
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

/* Closes a file just written: 0, or -1 with errno set when a write or the
 * close failed (a full disk, a file size limit); the failed file is then
 * removed, so no truncated mesh is left behind. */
static int finish_file(FILE *file, const char *path) {
    const int write_failed = ferror(file);
    int error = errno; /* the failed write's */
    const int close_failed = fclose(file) != 0;
    if (!write_failed && !close_failed) return 0;
    if (!write_failed) error = errno;
    remove(path);
    errno = error != 0 ? error : EIO;
    return -1;
}

static int write_mtl(const mesh_out *m, const char *path) {
    FILE *file = fopen(path, "w");
    size_t g;
    if (file == NULL) return -1;
    for (g = 0; g < m->group_count; ++g)
        fprintf(file, "newmtl %s\nKd %.3f %.3f %.3f\n\n", m->groups[g].name, m->groups[g].rgb[0] / 255.0,
                m->groups[g].rgb[1] / 255.0, m->groups[g].rgb[2] / 255.0);
    return finish_file(file, path);
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

int mesh_write_obj(const mesh_out *m, const char *path) {
    char mtl[4096];
    const char *slash = strrchr(path, '/');
    size_t *starts = malloc((m->group_count + 1) * sizeof *starts), *order, v;
    FILE *file;
    int status;
    if (starts == NULL || (order = faces_by_group(m, starts)) == NULL) {
        free(starts);
        return -1;
    }
    snprintf(mtl, sizeof mtl, "%s.mtl", path);
    file = write_mtl(m, mtl) == 0 ? fopen(path, "w") : NULL;
    if (file != NULL) {
        fprintf(file, "# octoprox export: %zu vertices, %zu faces, map frame, metres\nmtllib %s\n",
                m->vertex_count, m->face_count, slash ? mtl + (slash - path) + 1 : mtl);
        for (v = 0; v < m->vertex_count; ++v)
            fprintf(file, "v %.6f %.6f %.6f\n", m->vertices[3 * v], m->vertices[3 * v + 1], m->vertices[3 * v + 2]);
        write_obj_faces(file, m, order, starts);
    }
    status = file != NULL ? finish_file(file, path) : -1;
    if (status != 0) {
        const int error = errno;
        remove(mtl);
        errno = error;
    }
    free(order);
    free(starts);
    return status;
}

int mesh_write_ply(const mesh_out *m, const char *path) {
    FILE *file = fopen(path, "wb");
    size_t v, f;
    if (file == NULL) return -1;
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
    return finish_file(file, path);
}
