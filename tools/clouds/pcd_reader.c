/* PCD v0.7 reader: see pcd_reader.h. */
#include "pcd_reader.h"

#include "cloud_io.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PCD_MAX_FIELDS 32
#define PCD_LINE_MAX 4096

typedef struct pcd_header {
    int field_count;
    char names[PCD_MAX_FIELDS][32];
    int sizes[PCD_MAX_FIELDS];
    char types[PCD_MAX_FIELDS];
    int counts[PCD_MAX_FIELDS];
    int have_sizes, have_types, have_counts;
    long width, height, points;
    double viewpoint[7];
    char data[24];
} pcd_header;

/* Where x, y and z sit in one point record. */
typedef struct pcd_layout {
    size_t point_bytes;   /* binary: bytes of one point */
    size_t point_values;  /* ascii: numbers per point */
    size_t byte_offset[3];
    size_t byte_size[3];  /* 4: float32, 8: float64 */
    size_t value_index[3];
} pcd_layout;


static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/* Splits a line in place into whitespace-separated words; returns how many. */
static int split_words(char *line, char *words[], int max_words) {
    int n = 0;
    while (*line != '\0' && n < max_words) {
        while (is_space(*line)) *line++ = '\0';
        if (*line == '\0') break;
        words[n++] = line;
        while (*line != '\0' && !is_space(*line)) ++line;
        if (*line != '\0') *line++ = '\0';
    }
    return n;
}

static int parse_int_list(char *words[], int n, int out[], pcd_header *h) {
    int i;
    if (n - 1 != h->field_count) return -1;
    for (i = 1; i < n; ++i) out[i - 1] = atoi(words[i]);
    return 0;
}

/* Applies one header line; returns 0, or -1 with a message. */
static int apply_header_line(pcd_header *h, char *line, char *error, size_t error_size) {
    char *words[PCD_MAX_FIELDS + 1];
    const int n = split_words(line, words, PCD_MAX_FIELDS + 1);
    int i;
    if (n == 0 || words[0][0] == '#') return 0;
    if (strcmp(words[0], "FIELDS") == 0) {
        h->field_count = n - 1;
        for (i = 1; i < n; ++i) snprintf(h->names[i - 1], sizeof h->names[0], "%s", words[i]);
    } else if (strcmp(words[0], "SIZE") == 0) {
        h->have_sizes = parse_int_list(words, n, h->sizes, h) == 0;
    } else if (strcmp(words[0], "COUNT") == 0) {
        h->have_counts = parse_int_list(words, n, h->counts, h) == 0;
    } else if (strcmp(words[0], "TYPE") == 0) {
        h->have_types = n - 1 == h->field_count;
        for (i = 1; i < n && i <= PCD_MAX_FIELDS; ++i) h->types[i - 1] = words[i][0];
    } else if (strcmp(words[0], "WIDTH") == 0 && n == 2) {
        h->width = atol(words[1]);
    } else if (strcmp(words[0], "HEIGHT") == 0 && n == 2) {
        h->height = atol(words[1]);
    } else if (strcmp(words[0], "POINTS") == 0 && n == 2) {
        h->points = atol(words[1]);
    } else if (strcmp(words[0], "VIEWPOINT") == 0 && n == 8) {
        for (i = 0; i < 7; ++i) h->viewpoint[i] = atof(words[i + 1]);
    } else if (strcmp(words[0], "DATA") == 0 && n == 2) {
        snprintf(h->data, sizeof h->data, "%s", words[1]);
    } else if (strcmp(words[0], "VERSION") != 0) {
        cloud_set_error(error, error_size, "unexpected header line starting with \"%s\"", words[0]);
        return -1;
    }
    return 0;
}

/* Reads header lines up to and including DATA. */
static int read_header(FILE *file, pcd_header *h, char *error, size_t error_size) {
    char line[PCD_LINE_MAX];
    memset(h, 0, sizeof *h);
    h->height = 1;
    h->points = -1;
    while (h->data[0] == '\0') {
        if (fgets(line, sizeof line, file) == NULL) {
            cloud_set_error(error, error_size, "the header ends before a DATA line");
            return -1;
        }
        if (apply_header_line(h, line, error, error_size) != 0) return -1;
    }
    return 0;
}

static int find_field(const pcd_header *h, const char *name) {
    int i;
    for (i = 0; i < h->field_count; ++i)
        if (strcmp(h->names[i], name) == 0) return i;
    return -1;
}

/* Checks the header and computes where x, y and z are in a point. */
static int compute_layout(const pcd_header *h, pcd_layout *layout, char *error, size_t error_size) {
    static const char *const axes[3] = {"x", "y", "z"};
    int axis, i;
    if (h->field_count == 0 || !h->have_sizes || !h->have_types || !h->have_counts) {
        cloud_set_error(error, error_size, "FIELDS, SIZE, TYPE and COUNT must all be given, one entry per field");
        return -1;
    }
    for (axis = 0; axis < 3; ++axis) {
        const int f = find_field(h, axes[axis]);
        if (f < 0) {
            cloud_set_error(error, error_size, "no field \"%s\" in FIELDS", axes[axis]);
            return -1;
        }
        if (h->types[f] != 'F' || (h->sizes[f] != 4 && h->sizes[f] != 8) || h->counts[f] != 1) {
            cloud_set_error(error, error_size, "field \"%s\" is TYPE %c SIZE %d COUNT %d; only float32 "
                      "or float64 (F 4 1, F 8 1) is supported", axes[axis], h->types[f], h->sizes[f],
                      h->counts[f]);
            return -1;
        }
    }
    memset(layout, 0, sizeof *layout);
    for (i = 0; i < h->field_count; ++i) {
        if (h->sizes[i] <= 0 || h->sizes[i] > 8 || h->counts[i] <= 0 || h->counts[i] > 1 << 16) {
            cloud_set_error(error, error_size, "field \"%s\" has SIZE %d COUNT %d; sizes are 1..8 bytes",
                      h->names[i], h->sizes[i], h->counts[i]);
            return -1;
        }
        for (axis = 0; axis < 3; ++axis) {
            if (strcmp(h->names[i], axes[axis]) == 0) {
                layout->byte_offset[axis] = layout->point_bytes;
                layout->byte_size[axis] = (size_t)h->sizes[i];
                layout->value_index[axis] = layout->point_values;
            }
        }
        layout->point_bytes += (size_t)h->sizes[i] * (size_t)h->counts[i];
        layout->point_values += (size_t)h->counts[i];
    }
    return 0;
}

static int check_dimensions(const pcd_header *h, char *error, size_t error_size) {
    if (h->width <= 0 || h->height <= 0) {
        cloud_set_error(error, error_size, "WIDTH %ld and HEIGHT %ld must be positive", h->width, h->height);
        return -1;
    }
    if (h->points >= 0 && h->points != h->width * h->height) {
        cloud_set_error(error, error_size, "POINTS %ld is not WIDTH * HEIGHT = %ld", h->points, h->width * h->height);
        return -1;
    }
    return 0;
}

static int read_binary_points(FILE *file, const pcd_layout *layout, pcd_cloud *cloud,
                              char *error, size_t error_size) {
    unsigned char *record = malloc(layout->point_bytes);
    size_t i;
    int axis;
    if (record == NULL) {
        cloud_set_error(error, error_size, "out of memory");
        return -1;
    }
    for (i = 0; i < cloud->count; ++i) {
        if (fread(record, 1, layout->point_bytes, file) != layout->point_bytes) {
            cloud_set_error(error, error_size, "binary data truncated at point %zu of %zu", i, cloud->count);
            free(record);
            return -1;
        }
        for (axis = 0; axis < 3; ++axis) {
            const unsigned char *value = record + layout->byte_offset[axis];
            if (layout->byte_size[axis] == sizeof(double)) {
                double d;
                memcpy(&d, value, sizeof d);
                cloud->xyz[3 * i + axis] = (float)d;
            } else {
                memcpy(&cloud->xyz[3 * i + axis], value, sizeof(float));
            }
        }
    }
    free(record);
    return 0;
}

/* A whole word as a float ("nan" and "inf" included); -1 when it is not one. */
static int parse_float(const char *word, float *out) {
    char *end = NULL;
    *out = strtof(word, &end);
    return end == word || *end != '\0' ? -1 : 0;
}

static int read_ascii_points(FILE *file, const pcd_layout *layout, pcd_cloud *cloud,
                             char *error, size_t error_size) {
    char word[128];
    size_t i, v;
    int axis;
    for (i = 0; i < cloud->count; ++i) {
        for (v = 0; v < layout->point_values; ++v) {
            if (fscanf(file, "%127s", word) != 1) {
                cloud_set_error(error, error_size, "ascii data truncated at point %zu of %zu", i, cloud->count);
                return -1;
            }
            for (axis = 0; axis < 3; ++axis)
                if (layout->value_index[axis] == v && parse_float(word, &cloud->xyz[3 * i + axis]) != 0) {
                    cloud_set_error(error, error_size, "ascii value \"%s\" of point %zu is not a number", word, i);
                    return -1;
                }
        }
    }
    return 0;
}


static int read_points(FILE *file, const pcd_header *h, pcd_cloud *out, char *error, size_t error_size) {
    pcd_layout layout;
    if (strcmp(h->data, "binary_compressed") == 0) {
        cloud_set_error(error, error_size, "DATA binary_compressed (LZF) is unsupported; convert the "
                  "file to DATA binary or ascii first");
        return -1;
    }
    if (strcmp(h->data, "binary") != 0 && strcmp(h->data, "ascii") != 0) {
        cloud_set_error(error, error_size, "unknown DATA kind \"%s\"", h->data);
        return -1;
    }
    if (compute_layout(h, &layout, error, error_size) != 0) return -1;
    if (check_dimensions(h, error, error_size) != 0) return -1;
    out->width = (uint32_t)h->width;
    out->height = (uint32_t)h->height;
    out->count = (size_t)h->width * (size_t)h->height;
    memcpy(out->viewpoint, h->viewpoint, sizeof out->viewpoint);
    snprintf(out->data_format, sizeof out->data_format, "%s", h->data);
    out->xyz = malloc(out->count * 3 * sizeof(float));
    if (out->xyz == NULL) {
        cloud_set_error(error, error_size, "out of memory for %zu points", out->count);
        return -1;
    }
    if (strcmp(h->data, "binary") == 0) return read_binary_points(file, &layout, out, error, error_size);
    return read_ascii_points(file, &layout, out, error, error_size);
}

static int read_pcd(FILE *file, void *out, char *reason, size_t reason_size) {
    pcd_header header;
    const int status = read_header(file, &header, reason, reason_size);
    return status != 0 ? status : read_points(file, &header, out, reason, reason_size);
}

int pcd_read_file(const char *path, pcd_cloud *out, char *error, size_t error_size) {
    if (out == NULL || path == NULL) {
        cloud_set_error(error, error_size, "pcd_read_file: path and out must not be NULL");
        return -1;
    }
    memset(out, 0, sizeof *out);
    if (cloud_read_path(path, read_pcd, out, error, error_size) != 0) {
        pcd_free(out);
        return -1;
    }
    out->finite_count = cloud_count_finite(out->xyz, out->count);
    return 0;
}

void pcd_free(pcd_cloud *cloud) {
    if (cloud == NULL) return;
    free(cloud->xyz);
    memset(cloud, 0, sizeof *cloud);
}
