/* A minimal PNG writer: see png_writer.h.  The format: the 8-byte
 * signature, then chunks (length, type, data, CRC-32 of type and data):
 * IHDR, one IDAT holding the zlib stream of the scanlines (each prefixed
 * with filter byte 0, "none"), and IEND. */
#include "png_writer.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

static void put_u32(uint8_t *out, uint32_t v) {
    out[0] = (uint8_t)(v >> 24);
    out[1] = (uint8_t)(v >> 16);
    out[2] = (uint8_t)(v >> 8);
    out[3] = (uint8_t)v;
}

static int write_chunk(FILE *file, const char type[4], const uint8_t *data, uint32_t size) {
    uint8_t header[8], crc_bytes[4];
    uLong crc = crc32(0L, Z_NULL, 0);
    put_u32(header, size);
    memcpy(header + 4, type, 4);
    crc = crc32(crc, (const Bytef *)type, 4);
    if (size > 0) crc = crc32(crc, data, size);
    put_u32(crc_bytes, (uint32_t)crc);
    return fwrite(header, 1, 8, file) == 8 && (size == 0 || fwrite(data, 1, size, file) == size) &&
                   fwrite(crc_bytes, 1, 4, file) == 4
               ? 0
               : -1;
}

/* The scanlines with their filter bytes, compressed. */
static uint8_t *compress_rows(const uint8_t *rgb, uint32_t width, uint32_t height, uLongf *out_size) {
    const size_t row = (size_t)width * 3, raw_size = (row + 1) * height;
    uint8_t *raw = malloc(raw_size), *packed;
    uint32_t y;
    if (raw == NULL) return NULL;
    for (y = 0; y < height; ++y) {
        raw[y * (row + 1)] = 0;
        memcpy(raw + y * (row + 1) + 1, rgb + y * row, row);
    }
    *out_size = compressBound((uLong)raw_size);
    packed = malloc(*out_size);
    if (packed != NULL && compress2(packed, out_size, raw, (uLong)raw_size, 6) != Z_OK) {
        free(packed);
        packed = NULL;
    }
    free(raw);
    return packed;
}

int png_write_rgb(const char *path, const uint8_t *rgb, uint32_t width, uint32_t height) {
    static const uint8_t signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    uint8_t ihdr[13];
    uLongf packed_size = 0;
    uint8_t *packed = compress_rows(rgb, width, height, &packed_size);
    FILE *file;
    int status = -1;
    if (packed == NULL) return -1;
    put_u32(ihdr, width);
    put_u32(ihdr + 4, height);
    ihdr[8] = 8;   /* bits per channel */
    ihdr[9] = 2;   /* colour type: RGB */
    ihdr[10] = 0;  /* deflate */
    ihdr[11] = 0;  /* filtering: adaptive (we use "none" on every row) */
    ihdr[12] = 0;  /* no interlace */
    file = fopen(path, "wb");
    if (file != NULL) {
        status = fwrite(signature, 1, 8, file) == 8 && write_chunk(file, "IHDR", ihdr, 13) == 0 &&
                         write_chunk(file, "IDAT", packed, (uint32_t)packed_size) == 0 &&
                         write_chunk(file, "IEND", NULL, 0) == 0
                     ? 0
                     : -1;
        if (fclose(file) != 0) status = -1;
    }
    free(packed);
    return status;
}
