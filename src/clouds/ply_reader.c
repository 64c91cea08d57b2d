/* PLY vertex reader: see ply_reader.h. */
#define _POSIX_C_SOURCE 200809L
#include "ply_reader.h"

#include "cloud_io.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLY_MAX_ELEMENTS 16
#define PLY_MAX_PROPERTIES 64
#define PLY_LINE_MAX 1024
#define PLY_WORD_MAX 64
/* Items of one list at most (a face of a million corners is no face). */
#define PLY_MAX_LIST_ITEMS 1e6

typedef struct ply_property {
    char name[64];
    int type_size;      /* bytes of a scalar, or of a list's items */
    char type_kind;     /* 'i' signed, 'u' unsigned, 'f' floating */
    int is_list;
    int count_size;     /* list: bytes of the item count */
    char count_kind;
} ply_property;

typedef struct ply_element {
    char name[64];
    uint64_t count;  /* rows, at most CLOUD_MAX_POINTS */
    int property_count;
    ply_property properties[PLY_MAX_PROPERTIES];
} ply_element;

typedef struct ply_header {
    int binary;  /* 0 ascii, 1 binary_little_endian */
    char format[32];
    int element_count;
    ply_element elements[PLY_MAX_ELEMENTS];
} ply_header;


/* The size and kind of a PLY scalar type name; 0 when unknown. */
static int type_of(const char *name, char *kind) {
    static const struct { const char *name; int size; char kind; } types[] = {
        {"char", 1, 'i'}, {"int8", 1, 'i'}, {"uchar", 1, 'u'}, {"uint8", 1, 'u'},
        {"short", 2, 'i'}, {"int16", 2, 'i'}, {"ushort", 2, 'u'}, {"uint16", 2, 'u'},
        {"int", 4, 'i'}, {"int32", 4, 'i'}, {"uint", 4, 'u'}, {"uint32", 4, 'u'},
        {"float", 4, 'f'}, {"float32", 4, 'f'}, {"double", 8, 'f'}, {"float64", 8, 'f'},
    };
    size_t i;
    for (i = 0; i < sizeof types / sizeof types[0]; ++i) {
        if (strcmp(types[i].name, name) == 0) {
            *kind = types[i].kind;
            return types[i].size;
        }
    }
    return 0;
}

static int parse_property(ply_element *e, char *words[], int n, char *error, size_t error_size) {
    ply_property *p;
    if (e->property_count == PLY_MAX_PROPERTIES) {
        cloud_set_error(error, error_size, "element \"%s\" has more than %d properties", e->name, PLY_MAX_PROPERTIES);
        return -1;
    }
    p = &e->properties[e->property_count];
    memset(p, 0, sizeof *p);
    if (n == 5 && strcmp(words[1], "list") == 0) {
        p->is_list = 1;
        p->count_size = type_of(words[2], &p->count_kind);
        p->type_size = type_of(words[3], &p->type_kind);
        snprintf(p->name, sizeof p->name, "%s", words[4]);
        if (p->count_size == 0 || p->count_kind == 'f' || p->type_size == 0) {
            cloud_set_error(error, error_size, "bad list property \"%s %s %s\"", words[2], words[3], words[4]);
            return -1;
        }
    } else if (n == 3) {
        p->type_size = type_of(words[1], &p->type_kind);
        snprintf(p->name, sizeof p->name, "%s", words[2]);
        if (p->type_size == 0) {
            cloud_set_error(error, error_size, "unknown property type \"%s\"", words[1]);
            return -1;
        }
    } else {
        cloud_set_error(error, error_size, "malformed property line");
        return -1;
    }
    ++e->property_count;
    return 0;
}

static int split_words(char *line, char *words[], int max_words) {
    int n = 0;
    char *save = NULL, *word = strtok_r(line, " \t\r\n", &save);
    while (word != NULL && n < max_words) {
        words[n++] = word;
        word = strtok_r(NULL, " \t\r\n", &save);
    }
    return n;
}

static int parse_element(ply_header *h, char *words[], int n, char *error, size_t error_size) {
    ply_element *e;
    if (n != 3 || h->element_count == PLY_MAX_ELEMENTS) {
        cloud_set_error(error, error_size, "malformed element line (or more than %d elements)", PLY_MAX_ELEMENTS);
        return -1;
    }
    e = &h->elements[h->element_count++];
    memset(e, 0, sizeof *e);
    snprintf(e->name, sizeof e->name, "%s", words[1]);
    if (cloud_parse_count(words[2], CLOUD_MAX_POINTS, &e->count) != 0) {
        cloud_set_error(error, error_size, "element \"%s\" has a bad count \"%s\"", e->name, words[2]);
        return -1;
    }
    return 0;
}

static int parse_format(ply_header *h, char *words[], int n, char *error, size_t error_size) {
    if (n != 3) {
        cloud_set_error(error, error_size, "malformed format line");
        return -1;
    }
    snprintf(h->format, sizeof h->format, "%s", words[1]);
    if (strcmp(words[1], "ascii") == 0) h->binary = 0;
    else if (strcmp(words[1], "binary_little_endian") == 0) h->binary = 1;
    else {
        cloud_set_error(error, error_size, "format \"%s\" is unsupported (ascii and binary_little_endian are)", words[1]);
        return CLOUD_ERROR_UNSUPPORTED;
    }
    return 0;
}

/* One header line; returns 1 at end_header, 0 to go on, -1 on error. */
static int apply_header_line(ply_header *h, char *line, char *error, size_t error_size) {
    char *words[8];
    const int n = split_words(line, words, 8);
    if (n == 0 || strcmp(words[0], "comment") == 0 || strcmp(words[0], "obj_info") == 0) return 0;
    if (strcmp(words[0], "end_header") == 0) return 1;
    if (strcmp(words[0], "format") == 0) return parse_format(h, words, n, error, error_size);
    if (strcmp(words[0], "element") == 0) return parse_element(h, words, n, error, error_size);
    if (strcmp(words[0], "property") == 0) {
        if (h->element_count == 0) {
            cloud_set_error(error, error_size, "a property comes before any element");
            return -1;
        }
        return parse_property(&h->elements[h->element_count - 1], words, n, error, error_size);
    }
    cloud_set_error(error, error_size, "unexpected header line starting with \"%s\"", words[0]);
    return -1;
}

static int read_header(FILE *file, ply_header *h, char *error, size_t error_size) {
    char line[PLY_LINE_MAX];
    int status = 0;
    memset(h, 0, sizeof *h);
    if (cloud_read_line(file, line, sizeof line) != 0 || strncmp(line, "ply", 3) != 0 ||
        (line[3] != '\n' && line[3] != '\r')) {
        cloud_set_error(error, error_size, "not a PLY file (the first line is not \"ply\")");
        return -1;
    }
    while (status == 0) {
        const int got = cloud_read_line(file, line, sizeof line);
        if (got == -2) {
            cloud_set_error(error, error_size, "a header line is longer than %d bytes", PLY_LINE_MAX - 2);
            return -1;
        }
        if (got != 0) {
            cloud_set_error(error, error_size, "the header ends before end_header");
            return -1;
        }
        status = apply_header_line(h, line, error, error_size);
    }
    if (status < 0) return status;
    if (h->format[0] == '\0') {
        cloud_set_error(error, error_size, "no format line in the header");
        return -1;
    }
    return 0;
}

/* Reads one value (binary: `size` bytes of `kind`; ascii: one word). */
static int read_value(FILE *file, int binary, int size, char kind, double *out) {
    if (binary) {
        unsigned char b[8];
        if (fread(b, 1, (size_t)size, file) != (size_t)size) return -1;
        if (kind == 'f' && size == 4) { float f; memcpy(&f, b, 4); *out = f; }
        else if (kind == 'f') { double d; memcpy(&d, b, 8); *out = d; }
        else if (size == 1) *out = kind == 'i' ? (double)(int8_t)b[0] : (double)b[0];
        else if (size == 2) { uint16_t u; memcpy(&u, b, 2); *out = kind == 'i' ? (double)(int16_t)u : (double)u; }
        else { uint32_t u; memcpy(&u, b, 4); *out = kind == 'i' ? (double)(int32_t)u : (double)u; }
        return 0;
    }
    {
        char word[PLY_WORD_MAX], *end = NULL;
        const int status = cloud_read_word(file, word, sizeof word);
        if (status != 0) return status == -1 ? -1 : -2;
        *out = strtod(word, &end);
        return end == word || *end != '\0' ? -2 : 0;
    }
}

/* Reads one property of one row; *out gets a scalar's value. */
static int read_property(FILE *file, int binary, const ply_property *p, double *out) {
    double count, item;
    long i;
    int status;
    if (!p->is_list) return read_value(file, binary, p->type_size, p->type_kind, out);
    status = read_value(file, binary, p->count_size, p->count_kind, &count);
    if (status != 0) return status;
    if (count < 0 || count > PLY_MAX_LIST_ITEMS || count != floor(count)) return -2;
    for (i = 0; i < (long)count; ++i)
        if ((status = read_value(file, binary, p->type_size, p->type_kind, &item)) != 0) return status;
    *out = count;
    return 0;
}

static int row_error(int status, const ply_element *e, uint64_t row, char *error, size_t error_size) {
    if (status == -1)
        cloud_set_error(error, error_size, "data truncated in element \"%s\" at row %llu of %llu", e->name,
                        (unsigned long long)row, (unsigned long long)e->count);
    else
        cloud_set_error(error, error_size, "element \"%s\" row %llu holds a value that is not a number", e->name,
                        (unsigned long long)row);
    return -1;
}

/* The fewest bytes one row of e takes: binary, its scalars and its lists'
 * item counts (a list may be empty); ascii, one character and one blank
 * per property.  0 for an element without properties. */
static uint64_t min_row_bytes(const ply_element *e, int binary) {
    uint64_t bytes = 0;
    int k;
    for (k = 0; k < e->property_count; ++k) {
        const ply_property *p = &e->properties[k];
        bytes += !binary ? 2 : (uint64_t)(p->is_list ? p->count_size : p->type_size);
    }
    return bytes;
}

/* Refuses an element that announces more rows than the rest of the file
 * can hold (when the file has a known size), before any row is read. */
static int check_room(FILE *file, int binary, const ply_element *e, int *size_known, char *error,
                      size_t error_size) {
    const uint64_t row_bytes = min_row_bytes(e, binary);
    uint64_t left, most;
    *size_known = cloud_bytes_left(file, &left) == 0;
    if (!*size_known || row_bytes == 0) return 0;
    /* In ascii the very last blank may be missing. */
    most = (binary ? left : left + 1) / row_bytes;
    if (e->count > most) {
        cloud_set_error(error, error_size, "data truncated: element \"%s\" announces %llu rows, the %llu bytes "
                        "left hold at most %llu", e->name, (unsigned long long)e->count,
                        (unsigned long long)left, (unsigned long long)most);
        return -1;
    }
    return 0;
}

static int skip_element(FILE *file, int binary, const ply_element *e, char *error, size_t error_size) {
    uint64_t row;
    int k, status, size_known;
    double value;
    /* Rows without properties take no bytes: nothing to read. */
    if (e->property_count == 0) return 0;
    if (check_room(file, binary, e, &size_known, error, error_size) != 0) return -1;
    for (row = 0; row < e->count; ++row)
        for (k = 0; k < e->property_count; ++k)
            if ((status = read_property(file, binary, &e->properties[k], &value)) != 0)
                return row_error(status, e, row, error, error_size);
    return 0;
}

/* Where x, y and z are among the vertex properties; checks their types. */
static int find_xyz(const ply_element *e, int where[3], char *error, size_t error_size) {
    static const char *const axes[3] = {"x", "y", "z"};
    int axis, k;
    for (axis = 0; axis < 3; ++axis) {
        where[axis] = -1;
        for (k = 0; k < e->property_count; ++k)
            if (strcmp(e->properties[k].name, axes[axis]) == 0) where[axis] = k;
        if (where[axis] < 0) {
            cloud_set_error(error, error_size, "the vertex element has no property \"%s\"", axes[axis]);
            return -1;
        }
        if (e->properties[where[axis]].is_list || e->properties[where[axis]].type_kind != 'f') {
            cloud_set_error(error, error_size, "vertex property \"%s\" is not float or double", axes[axis]);
            return CLOUD_ERROR_UNSUPPORTED;
        }
    }
    return 0;
}

/* One vertex row; x, y and z go to xyz. */
static int read_vertex(FILE *file, int binary, const ply_element *e, const int where[3], float *xyz) {
    int k, axis, status;
    for (k = 0; k < e->property_count; ++k) {
        double value = 0.0;
        if ((status = read_property(file, binary, &e->properties[k], &value)) != 0) return status;
        for (axis = 0; axis < 3; ++axis)
            if (where[axis] == k) xyz[axis] = (float)value;
    }
    return 0;
}

static int read_vertices(FILE *file, int binary, const ply_element *e, ply_cloud *out,
                         char *error, size_t error_size) {
    int where[3], status, size_known;
    size_t row, capacity = 0;
    if ((status = find_xyz(e, where, error, error_size)) != 0) return status;
    if (check_room(file, binary, e, &size_known, error, error_size) != 0) return CLOUD_ERROR_CORRUPT;
    out->count = (size_t)e->count;
    if (cloud_reserve_points(&out->xyz, &capacity, cloud_first_capacity(out->count, size_known), out->count) != 0) {
        cloud_set_error(error, error_size, "out of memory for %zu vertices", out->count);
        return CLOUD_ERROR_NO_MEMORY;
    }
    for (row = 0; row < out->count; ++row) {
        if (cloud_reserve_points(&out->xyz, &capacity, row + 1, out->count) != 0) {
            cloud_set_error(error, error_size, "out of memory for %zu vertices", out->count);
            return CLOUD_ERROR_NO_MEMORY;
        }
        if ((status = read_vertex(file, binary, e, where, &out->xyz[3 * row])) != 0)
            return row_error(status, e, row, error, error_size);
    }
    return 0;
}

static int read_body(FILE *file, const ply_header *h, ply_cloud *out, char *error, size_t error_size) {
    int i;
    snprintf(out->format, sizeof out->format, "%s", h->format);
    for (i = 0; i < h->element_count; ++i) {
        const ply_element *e = &h->elements[i];
        if (strcmp(e->name, "vertex") == 0) return read_vertices(file, h->binary, e, out, error, error_size);
        if (skip_element(file, h->binary, e, error, error_size) != 0) return -1;
    }
    cloud_set_error(error, error_size, "no vertex element in the header");
    return -1;
}

static int read_ply(FILE *file, void *out, char *reason, size_t reason_size) {
    ply_header header;
    const int status = read_header(file, &header, reason, reason_size);
    return status != 0 ? status : read_body(file, &header, out, reason, reason_size);
}

int ply_read_file(const char *path, ply_cloud *out, char *error, size_t error_size) {
    int status;
    if (out == NULL || path == NULL) {
        cloud_set_error(error, error_size, "ply_read_file: path and out must not be NULL");
        return CLOUD_ERROR_INVALID;
    }
    memset(out, 0, sizeof *out);
    if ((status = cloud_read_path(path, read_ply, out, error, error_size)) != 0) {
        ply_free(out);
        return status;
    }
    out->finite_count = cloud_count_finite(out->xyz, out->count);
    return 0;
}

void ply_free(ply_cloud *cloud) {
    if (cloud == NULL) return;
    free(cloud->xyz);
    memset(cloud, 0, sizeof *cloud);
}
