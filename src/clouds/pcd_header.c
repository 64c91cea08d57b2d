/* The header of a PCD v0.7 file: see pcd_header.h. */
#include "pcd_header.h"

#include "cloud_io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define PCD_LINE_MAX 4096

static const char *const kAxes[3] = {"x", "y", "z"};

static int is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/* Splits a line in place into whitespace-separated words; returns how
 * many, or max_words + 1 when there are more than max_words. */
static int split_words(char *line, char *words[], int max_words) {
    int n = 0;
    for (;;) {
        while (is_space(*line)) *line++ = '\0';
        if (*line == '\0') return n;
        if (n == max_words) return max_words + 1;
        words[n++] = line;
        while (*line != '\0' && !is_space(*line)) ++line;
    }
}

static int is_axis(const char *name) {
    return strcmp(name, kAxes[0]) == 0 || strcmp(name, kAxes[1]) == 0 || strcmp(name, kAxes[2]) == 0;
}

static int parse_fields(pcd_header *h, char *words[], int n, char *error, size_t error_size) {
    int i, j;
    if (n < 2 || n - 1 > PCD_MAX_FIELDS) {
        cloud_set_error(error, error_size, "FIELDS must name 1 to %d fields", PCD_MAX_FIELDS);
        return -1;
    }
    h->field_count = n - 1;
    h->have_sizes = h->have_types = h->have_counts = 0;
    for (i = 1; i < n; ++i) {
        snprintf(h->names[i - 1], sizeof h->names[0], "%s", words[i]);
        /* Padding fields ("_") repeat in PCL's files; x, y and z may not. */
        for (j = 1; j < i; ++j)
            if (is_axis(words[i]) && strcmp(words[i], words[j]) == 0) {
                cloud_set_error(error, error_size, "field \"%s\" appears twice in FIELDS", words[i]);
                return -1;
            }
    }
    return 0;
}

/* SIZE or COUNT: one whole number in 1..max per field. */
static int parse_number_list(const pcd_header *h, char *words[], int n, int max, int out[], char *error,
                             size_t error_size) {
    int i;
    if (h->field_count == 0 || n - 1 != h->field_count) {
        cloud_set_error(error, error_size, "%s has %d entries, but FIELDS names %d fields", words[0], n - 1,
                        h->field_count);
        return -1;
    }
    for (i = 1; i < n; ++i) {
        uint64_t value;
        if (cloud_parse_count(words[i], (uint64_t)max, &value) != 0 || value == 0) {
            cloud_set_error(error, error_size, "%s entry \"%s\" is not a whole number in 1..%d", words[0], words[i],
                            max);
            return -1;
        }
        out[i - 1] = (int)value;
    }
    return 0;
}

static int parse_types(pcd_header *h, char *words[], int n, char *error, size_t error_size) {
    int i;
    if (h->field_count == 0 || n - 1 != h->field_count) {
        cloud_set_error(error, error_size, "TYPE has %d entries, but FIELDS names %d fields", n - 1, h->field_count);
        return -1;
    }
    for (i = 1; i < n; ++i) {
        if (words[i][1] != '\0' || strchr("IUF", words[i][0]) == NULL) {
            cloud_set_error(error, error_size, "TYPE entry \"%s\" is not I, U or F", words[i]);
            return -1;
        }
        h->types[i - 1] = words[i][0];
    }
    h->have_types = 1;
    return 0;
}

/* WIDTH, HEIGHT (1..2^32-1, as PCL stores them) or POINTS. */
static int parse_dimension(const char *key, const char *word, uint64_t min, uint64_t max, uint64_t *out,
                           char *error, size_t error_size) {
    if (cloud_parse_count(word, max, out) != 0 || *out < min) {
        cloud_set_error(error, error_size, "%s \"%s\" is not a whole number in %llu..%llu", key, word,
                        (unsigned long long)min, (unsigned long long)max);
        return -1;
    }
    return 0;
}

static int parse_viewpoint(pcd_header *h, char *words[], char *error, size_t error_size) {
    int i;
    for (i = 0; i < 7; ++i) {
        char *end = NULL;
        h->viewpoint[i] = strtod(words[i + 1], &end);
        if (end == words[i + 1] || *end != '\0' || !isfinite(h->viewpoint[i])) {
            cloud_set_error(error, error_size, "VIEWPOINT entry \"%s\" is not a finite number", words[i + 1]);
            return -1;
        }
    }
    h->have_viewpoint = 1;
    return 0;
}

/* The keywords with one value, and VIEWPOINT with seven. */
static int values_expected(const char *key) {
    static const char *const single[] = {"WIDTH", "HEIGHT", "POINTS", "DATA"};
    size_t i;
    for (i = 0; i < sizeof single / sizeof single[0]; ++i)
        if (strcmp(key, single[i]) == 0) return 1;
    return strcmp(key, "VIEWPOINT") == 0 ? 7 : -1;
}

/* Applies one header line; returns 0, or -1 with a message. */
static int apply_header_line(pcd_header *h, char *line, char *error, size_t error_size) {
    char *words[PCD_MAX_FIELDS + 2];
    const int n = split_words(line, words, PCD_MAX_FIELDS + 1);
    const char *key = n > 0 ? words[0] : "";
    const int expected = values_expected(key);
    if (n == 0 || key[0] == '#' || strcmp(key, "VERSION") == 0) return 0;
    if (expected > 0 && n - 1 != expected) {
        cloud_set_error(error, error_size, "%s needs %d value%s, not %d", key, expected, expected > 1 ? "s" : "",
                        n - 1);
        return -1;
    }
    if (strcmp(key, "FIELDS") == 0) return parse_fields(h, words, n, error, error_size);
    if (strcmp(key, "SIZE") == 0) {
        h->have_sizes = parse_number_list(h, words, n, 8, h->sizes, error, error_size) == 0;
        return h->have_sizes ? 0 : -1;
    }
    if (strcmp(key, "COUNT") == 0) {
        h->have_counts = parse_number_list(h, words, n, PCD_MAX_FIELD_COUNT, h->counts, error, error_size) == 0;
        return h->have_counts ? 0 : -1;
    }
    if (strcmp(key, "TYPE") == 0) return parse_types(h, words, n, error, error_size);
    if (strcmp(key, "WIDTH") == 0) return parse_dimension(key, words[1], 1, UINT32_MAX, &h->width, error, error_size);
    if (strcmp(key, "HEIGHT") == 0) return parse_dimension(key, words[1], 1, UINT32_MAX, &h->height, error, error_size);
    if (strcmp(key, "POINTS") == 0) {
        h->have_points = 1;
        return parse_dimension(key, words[1], 0, UINT64_MAX, &h->points, error, error_size);
    }
    if (strcmp(key, "VIEWPOINT") == 0) return parse_viewpoint(h, words, error, error_size);
    if (strcmp(key, "DATA") == 0) {
        snprintf(h->data, sizeof h->data, "%s", words[1]);
        return 0;
    }
    cloud_set_error(error, error_size, "unexpected header line starting with \"%.40s\"", key);
    return -1;
}

int pcd_read_header(FILE *file, pcd_header *h, char *error, size_t error_size) {
    char line[PCD_LINE_MAX];
    memset(h, 0, sizeof *h);
    h->height = 1;
    h->viewpoint[3] = 1.0; /* PCL's default VIEWPOINT: 0 0 0 1 0 0 0 */
    while (h->data[0] == '\0') {
        const int status = cloud_read_line(file, line, sizeof line);
        if (status == -2) {
            cloud_set_error(error, error_size, "a header line is longer than %d bytes", PCD_LINE_MAX - 2);
            return -1;
        }
        if (status != 0) {
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

static int check_axes(const pcd_header *h, char *error, size_t error_size) {
    int axis;
    for (axis = 0; axis < 3; ++axis) {
        const int f = find_field(h, kAxes[axis]);
        if (f < 0) {
            cloud_set_error(error, error_size, "no field \"%s\" in FIELDS", kAxes[axis]);
            return -1;
        }
        if (h->types[f] != 'F' || (h->sizes[f] != 4 && h->sizes[f] != 8) || h->counts[f] != 1) {
            cloud_set_error(error, error_size, "field \"%s\" is TYPE %c SIZE %d COUNT %d; only float32 "
                            "or float64 (F 4 1, F 8 1) is supported", kAxes[axis], h->types[f], h->sizes[f],
                            h->counts[f]);
            return CLOUD_ERROR_UNSUPPORTED;
        }
    }
    return 0;
}

int pcd_compute_layout(const pcd_header *h, pcd_layout *layout, char *error, size_t error_size) {
    int axis, i, status;
    if (h->field_count == 0 || !h->have_sizes || !h->have_types || !h->have_counts) {
        cloud_set_error(error, error_size, "FIELDS, SIZE, TYPE and COUNT must all be given, one entry per field");
        return -1;
    }
    if ((status = check_axes(h, error, error_size)) != 0) return status;
    memset(layout, 0, sizeof *layout);
    for (i = 0; i < h->field_count; ++i) {
        const int size = h->sizes[i];
        if (size != 1 && size != 2 && size != 4 && size != 8) {
            cloud_set_error(error, error_size, "field \"%s\" has SIZE %d; sizes are 1, 2, 4 or 8 bytes",
                            h->names[i], size);
            return -1;
        }
        for (axis = 0; axis < 3; ++axis) {
            if (strcmp(h->names[i], kAxes[axis]) == 0) {
                layout->byte_offset[axis] = layout->point_bytes;
                layout->byte_size[axis] = (size_t)size;
                layout->value_index[axis] = layout->point_values;
            }
        }
        /* At most 32 fields of 8 bytes * 65536: no overflow. */
        layout->point_bytes += (size_t)size * (size_t)h->counts[i];
        layout->point_values += (size_t)h->counts[i];
    }
    return 0;
}

int pcd_point_count(const pcd_header *h, size_t *count, char *error, size_t error_size) {
    uint64_t points;
    if (h->width == 0) {
        cloud_set_error(error, error_size, "no WIDTH line in the header");
        return -1;
    }
    /* Both are below 2^32, so the product fits in 64 bits. */
    points = h->width * h->height;
    if (h->have_points && h->points != points) {
        cloud_set_error(error, error_size, "POINTS %llu is not WIDTH * HEIGHT = %llu",
                        (unsigned long long)h->points, (unsigned long long)points);
        return -1;
    }
    if (points > CLOUD_MAX_POINTS) {
        /* A corrupt header, not a short machine: no file could hold them. */
        cloud_set_error(error, error_size, "WIDTH * HEIGHT = %llu points are more than this machine can hold",
                        (unsigned long long)points);
        return CLOUD_ERROR_CORRUPT;
    }
    *count = (size_t)points;
    return 0;
}
