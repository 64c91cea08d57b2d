/* PCD v0.7 reader: see pcd_reader.h. */
#include "pcd_reader.h"

#include "cloud_io.h"
#include "pcd_compressed.h"
#include "pcd_header.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PCD_WORD_MAX 128

/*
 * Refuses a header that announces more points than the rest of the file
 * can hold, before anything is allocated for them: a binary point takes
 * point_bytes, an ascii one at least one character and one blank per
 * value (the very last blank may be missing).  *size_known is 0 when the
 * file has no known size (a pipe): the points are then allocated as they
 * arrive.
 */
static int check_room(FILE *file, const pcd_layout *layout, int binary, size_t count, int *size_known,
                      char *error, size_t error_size) {
    uint64_t left, most;
    *size_known = cloud_bytes_left(file, &left) == 0;
    if (!*size_known) return 0;
    most = binary ? left / layout->point_bytes : (left + 1) / (2 * (uint64_t)layout->point_values);
    if ((uint64_t)count > most) {
        cloud_set_error(error, error_size, "%s data truncated: the header announces %zu points, the %llu bytes "
                        "after it hold at most %llu", binary ? "binary" : "ascii", count,
                        (unsigned long long)left, (unsigned long long)most);
        return CLOUD_ERROR_CORRUPT;
    }
    return 0;
}

static int out_of_memory(size_t count, char *error, size_t error_size) {
    cloud_set_error(error, error_size, "out of memory for %zu points", count);
    return CLOUD_ERROR_NO_MEMORY;
}

static void decode_binary_point(const unsigned char *record, const pcd_layout *layout, float *xyz) {
    int axis;
    for (axis = 0; axis < 3; ++axis) {
        const unsigned char *value = record + layout->byte_offset[axis];
        if (layout->byte_size[axis] == sizeof(double)) {
            double d;
            memcpy(&d, value, sizeof d);
            xyz[axis] = (float)d;
        } else {
            memcpy(&xyz[axis], value, sizeof(float));
        }
    }
}

static int read_binary_points(FILE *file, const pcd_layout *layout, pcd_cloud *cloud, size_t *capacity,
                              char *error, size_t error_size) {
    unsigned char *record = malloc(layout->point_bytes);
    size_t i;
    int status = 0;
    if (record == NULL) return out_of_memory(cloud->count, error, error_size);
    for (i = 0; i < cloud->count && status == 0; ++i) {
        if (fread(record, 1, layout->point_bytes, file) != layout->point_bytes) {
            cloud_set_error(error, error_size, "binary data truncated at point %zu of %zu", i, cloud->count);
            status = CLOUD_ERROR_CORRUPT;
        } else if (cloud_reserve_points(&cloud->xyz, capacity, i + 1, cloud->count) != 0) {
            status = out_of_memory(cloud->count, error, error_size);
        } else {
            decode_binary_point(record, layout, &cloud->xyz[3 * i]);
        }
    }
    free(record);
    return status;
}

/* A whole word as a float ("nan" and "inf" included); -1 when it is not one. */
static int parse_float(const char *word, float *out) {
    char *end = NULL;
    *out = strtof(word, &end);
    return end == word || *end != '\0' ? -1 : 0;
}

/* The point_values numbers of point i; x, y and z go to xyz. */
static int read_ascii_point(FILE *file, const pcd_layout *layout, size_t i, size_t count, float *xyz,
                            char *error, size_t error_size) {
    char word[PCD_WORD_MAX];
    size_t v;
    int axis;
    for (v = 0; v < layout->point_values; ++v) {
        const int status = cloud_read_word(file, word, sizeof word);
        if (status == -1) {
            cloud_set_error(error, error_size, "ascii data truncated at point %zu of %zu", i, count);
            return CLOUD_ERROR_CORRUPT;
        }
        if (status != 0) {
            cloud_set_error(error, error_size, "ascii value of point %zu is longer than %d characters", i,
                            PCD_WORD_MAX - 1);
            return CLOUD_ERROR_CORRUPT;
        }
        for (axis = 0; axis < 3; ++axis)
            if (layout->value_index[axis] == v && parse_float(word, &xyz[axis]) != 0) {
                cloud_set_error(error, error_size, "ascii value \"%s\" of point %zu is not a number", word, i);
                return CLOUD_ERROR_CORRUPT;
            }
    }
    return 0;
}

static int read_ascii_points(FILE *file, const pcd_layout *layout, pcd_cloud *cloud, size_t *capacity,
                             char *error, size_t error_size) {
    size_t i;
    int status;
    for (i = 0; i < cloud->count; ++i) {
        if (cloud_reserve_points(&cloud->xyz, capacity, i + 1, cloud->count) != 0)
            return out_of_memory(cloud->count, error, error_size);
        status = read_ascii_point(file, layout, i, cloud->count, &cloud->xyz[3 * i], error, error_size);
        if (status != 0) return status;
    }
    return 0;
}

static int check_data_kind(const char *data, char *error, size_t error_size) {
    if (strcmp(data, "binary") != 0 && strcmp(data, "ascii") != 0 && strcmp(data, "binary_compressed") != 0) {
        cloud_set_error(error, error_size, "unknown DATA kind \"%s\"", data);
        return CLOUD_ERROR_CORRUPT;
    }
    return 0;
}

/* The header's description of the cloud, before its points. */
static void describe(const pcd_header *h, size_t count, pcd_cloud *out) {
    out->width = (uint32_t)h->width;
    out->height = (uint32_t)h->height;
    out->count = count;
    memcpy(out->viewpoint, h->viewpoint, sizeof out->viewpoint);
    out->has_viewpoint = h->have_viewpoint;
    snprintf(out->data_format, sizeof out->data_format, "%s", h->data);
}

/* DATA binary or ascii: point after point. */
static int read_records(FILE *file, const pcd_layout *layout, int binary, pcd_cloud *out, char *error,
                        size_t error_size) {
    size_t capacity = 0;
    int size_known, status;
    if ((status = check_room(file, layout, binary, out->count, &size_known, error, error_size)) != 0) return status;
    if (cloud_reserve_points(&out->xyz, &capacity, cloud_first_capacity(out->count, size_known), out->count) != 0)
        return out_of_memory(out->count, error, error_size);
    if (binary) return read_binary_points(file, layout, out, &capacity, error, error_size);
    return read_ascii_points(file, layout, out, &capacity, error, error_size);
}

static int read_points(FILE *file, const pcd_header *h, pcd_cloud *out, char *error, size_t error_size) {
    pcd_layout layout;
    size_t count;
    int status;
    if ((status = check_data_kind(h->data, error, error_size)) != 0) return status;
    if ((status = pcd_compute_layout(h, &layout, error, error_size)) != 0) return status;
    if ((status = pcd_point_count(h, &count, error, error_size)) != 0) return status;
    describe(h, count, out);
    if (strcmp(h->data, "binary_compressed") == 0)
        return pcd_read_compressed(file, &layout, count, &out->xyz, error, error_size);
    return read_records(file, &layout, strcmp(h->data, "binary") == 0, out, error, error_size);
}

static int read_pcd(FILE *file, void *out, char *reason, size_t reason_size) {
    pcd_header header;
    const int status = pcd_read_header(file, &header, reason, reason_size);
    return status != 0 ? status : read_points(file, &header, out, reason, reason_size);
}

int pcd_read_file(const char *path, pcd_cloud *out, char *error, size_t error_size) {
    int status;
    if (out == NULL || path == NULL) {
        cloud_set_error(error, error_size, "pcd_read_file: path and out must not be NULL");
        return CLOUD_ERROR_INVALID;
    }
    memset(out, 0, sizeof *out);
    if ((status = cloud_read_path(path, read_pcd, out, error, error_size)) != 0) {
        pcd_free(out);
        return status;
    }
    out->finite_count = cloud_count_finite(out->xyz, out->count);
    return 0;
}

void pcd_free(pcd_cloud *cloud) {
    if (cloud == NULL) return;
    free(cloud->xyz);
    memset(cloud, 0, sizeof *cloud);
}
