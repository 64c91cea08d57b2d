/*
 * The header of a PCD v0.7 file (internal to opx_clouds): its lines up to
 * DATA, checked, and where x, y and z sit in one point.
 */
#ifndef OPX_CLOUDS_PCD_HEADER_H
#define OPX_CLOUDS_PCD_HEADER_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define PCD_MAX_FIELDS 32
/* COUNT of one field at most (PCL's largest descriptors hold ~2000). */
#define PCD_MAX_FIELD_COUNT 65536

typedef struct pcd_header {
    int field_count;
    char names[PCD_MAX_FIELDS][32];
    int sizes[PCD_MAX_FIELDS];
    char types[PCD_MAX_FIELDS];
    int counts[PCD_MAX_FIELDS];
    int have_sizes, have_types, have_counts, have_points;
    uint64_t width, height, points; /* WIDTH and HEIGHT fit in 32 bits */
    double viewpoint[7];  /* tx ty tz qw qx qy qz; 0 0 0 1 0 0 0 without a VIEWPOINT line */
    int have_viewpoint;
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

/* Reads the header lines up to and including DATA; 0, or a
 * CLOUD_ERROR_* with a message. */
int pcd_read_header(FILE *file, pcd_header *h, char *error, size_t error_size);

/* Checks FIELDS, SIZE, TYPE and COUNT and computes the layout; 0, or a
 * CLOUD_ERROR_* with a message. */
int pcd_compute_layout(const pcd_header *h, pcd_layout *layout, char *error, size_t error_size);

/* WIDTH * HEIGHT, checked against POINTS and CLOUD_MAX_POINTS; 0 and
 * *count set, or a CLOUD_ERROR_* with a message. */
int pcd_point_count(const pcd_header *h, size_t *count, char *error, size_t error_size);

#endif /* OPX_CLOUDS_PCD_HEADER_H */
