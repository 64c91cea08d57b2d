/* PCD DATA binary_compressed: see pcd_compressed.h. */
#include "pcd_compressed.h"

#include "cloud_io.h"

#include <lzf.h>

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* The most bytes one byte of LZF data can stand for: a back reference of
 * three bytes copies at most 264 (LZF's longest match). */
#define LZF_MAX_EXPANSION 88u
/* Blocks of unknown room (a pipe) are read in slices growing from this. */
#define FIRST_SLICE ((size_t)1 << 20)

static int no_memory(char *error, size_t error_size, uint32_t bytes) {
    cloud_set_error(error, error_size, "out of memory for %lu bytes of compressed data", (unsigned long)bytes);
    return CLOUD_ERROR_NO_MEMORY;
}

static uint32_t le32(const unsigned char *b) {
    return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

/* The two sizes after DATA. */
static int read_sizes(FILE *file, uint32_t *packed, uint32_t *unpacked, char *error, size_t error_size) {
    unsigned char b[8];
    const size_t got = fread(b, 1, sizeof b, file);
    if (got != sizeof b) {
        cloud_set_error(error, error_size, "binary_compressed data truncated: %zu of the 8 bytes of its two sizes",
                        got);
        return CLOUD_ERROR_CORRUPT;
    }
    *packed = le32(b);
    *unpacked = le32(b + 4);
    return 0;
}

/* The sizes against the header, each other and the bytes left. */
static int check_sizes(FILE *file, const pcd_layout *layout, size_t count, uint32_t packed, uint32_t unpacked,
                       int *size_known, char *error, size_t error_size) {
    /* Below 2^32 each, so the product fits in 64 bits. */
    const uint64_t needed = count > UINT32_MAX || layout->point_bytes > UINT32_MAX
                                ? UINT64_MAX
                                : (uint64_t)count * layout->point_bytes;
    uint64_t left;
    if (unpacked != needed) {
        cloud_set_error(error, error_size, "binary_compressed: the block decompresses to %lu bytes, not POINTS x "
                        "point size = %zu x %zu", (unsigned long)unpacked, count, layout->point_bytes);
        return CLOUD_ERROR_CORRUPT;
    }
    if ((uint64_t)unpacked > (uint64_t)packed * LZF_MAX_EXPANSION) {
        cloud_set_error(error, error_size, "binary_compressed: %lu bytes of LZF data cannot decompress to %lu bytes",
                        (unsigned long)packed, (unsigned long)unpacked);
        return CLOUD_ERROR_CORRUPT;
    }
    *size_known = cloud_bytes_left(file, &left) == 0;
    if (*size_known && packed > left) {
        cloud_set_error(error, error_size, "binary_compressed data truncated: a block of %lu bytes, %llu left in "
                        "the file", (unsigned long)packed, (unsigned long long)left);
        return CLOUD_ERROR_CORRUPT;
    }
    return 0;
}

/* The compressed block: all at once when the file's size bounded it,
 * else in growing slices, so a lying size on a pipe costs no more memory
 * than the bytes that really arrive. */
static int read_block(FILE *file, uint32_t size, int size_known, unsigned char **out, char *error,
                      size_t error_size) {
    size_t have = 0, room = size_known || size < FIRST_SLICE ? size : FIRST_SLICE;
    unsigned char *block = malloc(room + 1);
    while (block != NULL) {
        have += fread(block + have, 1, room - have, file);
        if (have == size) {
            *out = block;
            return 0;
        }
        if (have < room) {
            free(block);
            cloud_set_error(error, error_size, "binary_compressed data truncated: %zu of the block's %lu bytes", have,
                            (unsigned long)size);
            return CLOUD_ERROR_CORRUPT;
        }
        room = room > size / 2 ? size : 2 * room;
        {
            unsigned char *grown = realloc(block, room + 1);
            if (grown == NULL) free(block);
            block = grown;
        }
    }
    return no_memory(error, error_size, size);
}

static void gather_points(const unsigned char *fields, const pcd_layout *layout, size_t count, float *xyz) {
    size_t i;
    int axis;
    for (axis = 0; axis < 3; ++axis) {
        const size_t size = layout->byte_size[axis];
        const unsigned char *column = fields + count * layout->byte_offset[axis];
        for (i = 0; i < count; ++i) {
            if (size == sizeof(double)) {
                double d;
                memcpy(&d, column + i * size, sizeof d);
                xyz[3 * i + (size_t)axis] = (float)d;
            } else {
                memcpy(&xyz[3 * i + (size_t)axis], column + i * size, sizeof(float));
            }
        }
    }
}

static int decompress(const unsigned char *block, uint32_t packed, uint32_t unpacked, unsigned char *fields,
                      char *error, size_t error_size) {
    unsigned int got;
    if (unpacked == 0) return 0;
    errno = 0;
    got = lzf_decompress(block, packed, fields, unpacked);
    if (got == unpacked) return 0;
    if (got == 0 && errno == E2BIG)
        cloud_set_error(error, error_size, "binary_compressed: the LZF data decompresses to more than the %lu "
                        "bytes announced", (unsigned long)unpacked);
    else if (got == 0)
        cloud_set_error(error, error_size, "binary_compressed: corrupt LZF data (a reference before the start, or "
                        "a run past the end of the block)");
    else
        cloud_set_error(error, error_size, "binary_compressed: the LZF data decompresses to %u bytes, not the %lu "
                        "announced", got, (unsigned long)unpacked);
    return CLOUD_ERROR_CORRUPT;
}

int pcd_read_compressed(FILE *file, const pcd_layout *layout, size_t count, float **xyz, char *error,
                        size_t error_size) {
    uint32_t packed, unpacked;
    unsigned char *block = NULL, *fields = NULL;
    int size_known, status;
    if ((status = read_sizes(file, &packed, &unpacked, error, error_size)) != 0) return status;
    status = check_sizes(file, layout, count, packed, unpacked, &size_known, error, error_size);
    if (status != 0) return status;
    if ((status = read_block(file, packed, size_known, &block, error, error_size)) != 0) return status;
    fields = malloc((size_t)unpacked + 1);
    *xyz = malloc(count * 3 * sizeof(float) + 1);
    if (fields == NULL || *xyz == NULL) status = no_memory(error, error_size, unpacked);
    else status = decompress(block, packed, unpacked, fields, error, error_size);
    if (status == 0) gather_points(fields, layout, count, *xyz);
    free(block);
    free(fields);
    return status;
}
