/*
 * 16-bit depth images from files, for the octoprox tool and the tests:
 *   PNG  through libpng: 16-bit grayscale (the TUM RGB-D convention;
 *        interlaced files too);
 *   TIFF through libtiff: 16-bit unsigned, one sample per pixel, minimum
 *        is black, stored in strips (any compression libtiff reads); the
 *        file's first image.
 * The format is told by the file's first bytes, not its name.  Pixels are
 * the file's raw depth units: the caller knows their scale (PNG from TUM:
 * 5000 a metre; OpenNI TIFF: millimetres).  Malformed or truncated files,
 * other pixel types and images of more than DEPTH_IMAGE_MAX_PIXELS pixels
 * are errors with a message naming the file, before their pixels are
 * allocated.
 */
#ifndef OPX_CLOUDS_DEPTH_IMAGE_H
#define OPX_CLOUDS_DEPTH_IMAGE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* 2^26 pixels (128 MiB of depth): 8192 x 8192, far beyond any depth camera. */
#define DEPTH_IMAGE_MAX_PIXELS ((uint64_t)1 << 26)

typedef struct depth_image {
    uint16_t *pixels; /* width * height, row after row, left to right; native byte order */
    uint32_t width;
    uint32_t height;
    char format[24];  /* "png 16-bit gray" or "tiff 16-bit gray" */
} depth_image;

/* 1 when the path ends in .png, .tif or .tiff (any case), else 0. */
int depth_image_file_supported(const char *path);

/* Reads a depth image into *out (zeroed first).  0 on success; -1 with a
 * message naming the file in error (error_size bytes, may be 0), *out
 * left empty. */
int depth_image_read_file(const char *path, depth_image *out, char *error, size_t error_size);

/* Frees the pixels; NULL is a no-op. */
void depth_image_free(depth_image *image);

#ifdef __cplusplus
}
#endif

#endif /* OPX_CLOUDS_DEPTH_IMAGE_H */
