/* Seeds of fuzz_depth: small 16-bit depth images as PNG and as TIFF
 * (uncompressed and deflated), written with libpng and libtiff. */
#include "seeds.h"

#include <png.h>
#include <tiffio.h>

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

enum { kWidth = 5, kHeight = 3 };

static uint16_t depth_at(uint32_t u, uint32_t v) { return (uint16_t)((u + v) % 4 == 0 ? 0 : 500 + 97 * u + 311 * v); }

typedef struct {
    unsigned char *bytes;
    size_t size;
} byte_buffer;

static void append_png_bytes(png_structp png, png_bytep data, png_size_t length) {
    byte_buffer *buffer = png_get_io_ptr(png);
    unsigned char *grown = realloc(buffer->bytes, buffer->size + length);
    if (grown == NULL) png_error(png, "out of memory");
    memcpy(grown + buffer->size, data, length);
    buffer->bytes = grown;
    buffer->size += length;
}

static void flush_nothing(png_structp png) { (void)png; }

static void write_png_seed(const char *out_dir, const char *name, int interlace) {
    byte_buffer buffer = {NULL, 0};
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (png == NULL || info == NULL || setjmp(png_jmpbuf(png))) {
        fprintf(stderr, "make_seeds: libpng cannot write %s\n", name);
        exit(1);
    }
    png_set_write_fn(png, &buffer, append_png_bytes, flush_nothing);
    png_set_IHDR(png, info, kWidth, kHeight, 16, PNG_COLOR_TYPE_GRAY, interlace, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    const int passes = png_set_interlace_handling(png);
    for (int pass = 0; pass < passes; ++pass)
        for (uint32_t v = 0; v < kHeight; ++v) {
            unsigned char row[2 * kWidth];
            for (uint32_t u = 0; u < kWidth; ++u) {
                row[2 * u] = (unsigned char)(depth_at(u, v) >> 8); /* PNG is big-endian */
                row[2 * u + 1] = (unsigned char)(depth_at(u, v) & 0xff);
            }
            png_write_row(png, row);
        }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    write_seed(out_dir, "fuzz_depth", name, buffer.bytes, buffer.size);
    free(buffer.bytes);
}

/* libtiff writes to a file: a scratch file, read back into the seed. */
static void write_tiff_seed(const char *out_dir, const char *name, int compression) {
    char path[] = "/tmp/opx_seed_tiff_XXXXXX";
    const int fd = mkstemp(path);
    TIFF *tif = fd < 0 ? NULL : TIFFOpen(path, "w");
    if (tif == NULL) {
        fprintf(stderr, "make_seeds: libtiff cannot write %s\n", name);
        exit(1);
    }
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, kWidth);
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, kHeight);
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 16);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(tif, TIFFTAG_SAMPLEFORMAT, SAMPLEFORMAT_UINT);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(tif, TIFFTAG_PLANARCONFIG, PLANARCONFIG_CONTIG);
    TIFFSetField(tif, TIFFTAG_COMPRESSION, compression);
    TIFFSetField(tif, TIFFTAG_ROWSPERSTRIP, 2);
    for (uint32_t v = 0; v < kHeight; ++v) {
        uint16_t row[kWidth];
        for (uint32_t u = 0; u < kWidth; ++u) row[u] = depth_at(u, v);
        TIFFWriteScanline(tif, row, v, 0);
    }
    TIFFClose(tif);
    FILE *file = fdopen(fd, "rb");
    unsigned char bytes[4096];
    const size_t size = file ? fread(bytes, 1, sizeof bytes, file) : 0;
    if (file) fclose(file);
    unlink(path);
    if (size == 0 || size == sizeof bytes) {
        fprintf(stderr, "make_seeds: cannot read back %s\n", name);
        exit(1);
    }
    write_seed(out_dir, "fuzz_depth", name, bytes, size);
}

void write_depth_seeds(const char *out_dir) {
    write_png_seed(out_dir, "gray16.png", PNG_INTERLACE_NONE);
    write_png_seed(out_dir, "gray16_interlaced.png", PNG_INTERLACE_ADAM7);
    write_tiff_seed(out_dir, "gray16.tiff", COMPRESSION_NONE);
    write_tiff_seed(out_dir, "gray16_deflate.tiff", COMPRESSION_ADOBE_DEFLATE);
}
