/* Depth image files for the tests: see depth_files.h. */
#include "depth_files.h"

#include "cli_run.h"

#include <png.h>
#include <tiffio.h>

#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

const char *write_png(const char *name, const uint16_t *pixels, uint32_t width, uint32_t height, int bit_depth,
                      int channels) {
    const char *path = scratch_path(name);
    FILE *file = fopen(path, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    const size_t values = (size_t)width * channels;
    unsigned char *row = malloc(values * 2);
    uint32_t v;
    size_t i;
    if (file == NULL || png == NULL || info == NULL || row == NULL) fail_msg("cannot write %s", path);
    if (setjmp(png_jmpbuf(png))) fail_msg("libpng failed writing %s", path);
    png_init_io(png, file);
    png_set_IHDR(png, info, width, height, bit_depth, channels == 1 ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (v = 0; v < height; ++v) {
        const uint16_t *src = pixels + (size_t)v * values;
        for (i = 0; i < values; ++i) {
            if (bit_depth == 16) {
                row[2 * i] = (unsigned char)(src[i] >> 8); /* PNG is big-endian */
                row[2 * i + 1] = (unsigned char)(src[i] & 0xff);
            } else {
                row[i] = (unsigned char)src[i];
            }
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(row);
    fclose(file);
    return path;
}

/* One row of `samples * width` values as the TIFF stores them. */
static void fill_tiff_row(unsigned char *out, const uint16_t *src, size_t values, int bits) {
    size_t i;
    for (i = 0; i < values; ++i) {
        if (bits == 16) {
            memcpy(out + 2 * i, &src[i], 2);
        } else if (bits == 32) {
            const float value = (float)src[i] / 1000.0f;
            memcpy(out + 4 * i, &value, 4);
        } else {
            out[i] = (unsigned char)src[i];
        }
    }
}

const char *write_tiff(const char *name, const uint16_t *pixels, uint32_t width, uint32_t height, int bits,
                       int samples, int compression) {
    const char *path = scratch_path(name);
    TIFF *tif = TIFFOpen(path, "w");
    const size_t values = (size_t)width * samples;
    unsigned char *row = malloc(values * 4);
    uint32_t v;
    if (tif == NULL || row == NULL) fail_msg("cannot write %s", path);
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, width);
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, height);
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, bits);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, samples);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, bits == 32 ? SAMPLEFORMAT_IEEEFP : SAMPLEFORMAT_UINT);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, samples == 1 ? PHOTOMETRIC_MINISBLACK : PHOTOMETRIC_RGB);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_COMPRESSION, compression);
    TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, 1);
    for (v = 0; v < height; ++v) {
        fill_tiff_row(row, pixels + (size_t)v * values, values, bits);
        if (TIFFWriteScanline(tif, row, v, 0) < 0) fail_msg("libtiff failed writing %s", path);
    }
    TIFFClose(tif);
    free(row);
    return path;
}

static void put16(unsigned char *p, uint16_t v) { p[0] = (unsigned char)v, p[1] = (unsigned char)(v >> 8); }
static void put32(unsigned char *p, uint32_t v) { put16(p, (uint16_t)v), put16(p + 2, (uint16_t)(v >> 16)); }

static unsigned char *ifd_entry(unsigned char *p, uint16_t tag, uint16_t type, uint32_t value) {
    put16(p, tag);
    put16(p + 2, type); /* 3 SHORT, 4 LONG */
    put32(p + 4, 1);
    put32(p + 8, value); /* a SHORT sits in the first two bytes */
    return p + 12;
}

const char *write_raw_tiff(const char *name, uint32_t width, uint32_t height, uint32_t strip_bytes,
                           uint32_t present_bytes) {
    enum { ENTRIES = 9, DATA = 8 + 2 + ENTRIES * 12 + 4 };
    unsigned char *bytes = calloc(1, DATA + present_bytes);
    unsigned char *p = bytes + 10;
    const char *path;
    if (bytes == NULL) fail_msg("out of memory");
    memcpy(bytes, "II*\0", 4);
    put32(bytes + 4, 8);
    put16(bytes + 8, ENTRIES);
    p = ifd_entry(p, 256, 4, width);
    p = ifd_entry(p, 257, 4, height);
    p = ifd_entry(p, 258, 3, 16);        /* BitsPerSample */
    p = ifd_entry(p, 259, 3, 1);         /* no compression */
    p = ifd_entry(p, 262, 3, 1);         /* min-is-black */
    p = ifd_entry(p, 273, 4, DATA);      /* the strip's offset */
    p = ifd_entry(p, 277, 3, 1);         /* SamplesPerPixel */
    p = ifd_entry(p, 278, 4, height);    /* RowsPerStrip */
    ifd_entry(p, 279, 4, strip_bytes);   /* StripByteCounts; next IFD offset 0 follows */
    path = write_bytes(name, bytes, DATA + present_bytes);
    free(bytes);
    return path;
}

/* CRC-32 of PNG chunks (ISO 3309), bit by bit. */
static uint32_t crc32_of(const unsigned char *bytes, size_t size) {
    uint32_t crc = 0xffffffffu;
    size_t i;
    int bit;
    for (i = 0; i < size; ++i) {
        crc ^= bytes[i];
        for (bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

static void put32be(unsigned char *p, uint32_t v) {
    p[0] = (unsigned char)(v >> 24), p[1] = (unsigned char)(v >> 16), p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* A chunk (length, type, data, CRC) at p; returns the end. */
static unsigned char *png_chunk(unsigned char *p, const char *type, const unsigned char *data, uint32_t size) {
    put32be(p, size);
    memcpy(p + 4, type, 4);
    if (size > 0) memcpy(p + 8, data, size);
    put32be(p + 8 + size, crc32_of(p + 4, 4 + size));
    return p + 12 + size;
}

const char *write_raw_png_header(const char *name, uint32_t width, uint32_t height) {
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char bytes[8 + 25 + 12 + 12], ihdr[13] = {0}, *p = bytes + 8;
    memcpy(bytes, signature, 8);
    put32be(ihdr, width);
    put32be(ihdr + 4, height);
    ihdr[8] = 16; /* bit depth; colour type 0 (gray), no interlace */
    p = png_chunk(p, "IHDR", ihdr, 13);
    p = png_chunk(p, "IDAT", NULL, 0);
    p = png_chunk(p, "IEND", NULL, 0);
    return write_bytes(name, bytes, (size_t)(p - bytes));
}

size_t file_size(const char *path) {
    FILE *file = fopen(path, "rb");
    long size = 0;
    if (file == NULL || fseek(file, 0, SEEK_END) != 0 || (size = ftell(file)) < 0) fail_msg("cannot size %s", path);
    fclose(file);
    return (size_t)size;
}

const char *write_prefix(const char *name, const char *from, size_t size) {
    FILE *file = fopen(from, "rb");
    unsigned char *bytes = malloc(size + 1);
    const char *path;
    if (file == NULL || bytes == NULL || fread(bytes, 1, size, file) != size) fail_msg("cannot read %s", from);
    fclose(file);
    path = write_bytes(name, bytes, size);
    free(bytes);
    return path;
}
