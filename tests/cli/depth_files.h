/*
 * Depth image files written by the tests into the scratch folder: 16-bit
 * (or other) PNGs through libpng and TIFFs through libtiff, and small
 * TIFF and PNG files laid out byte by byte, for headers no library would
 * write (huge sizes, missing pixel data).
 */
#ifndef OPX_TESTS_DEPTH_FILES_H
#define OPX_TESTS_DEPTH_FILES_H

#include <stddef.h>
#include <stdint.h>

/* A PNG of `channels` channels (1: gray, 3: RGB) and bit depth 8 or 16;
 * `pixels` holds width * height * channels values (0..255 for 8 bits). */
const char *write_png(const char *name, const uint16_t *pixels, uint32_t width, uint32_t height, int bit_depth,
                      int channels);

/* A TIFF of one strip per row, `compression` COMPRESSION_NONE or
 * COMPRESSION_PACKBITS; `bits` 8 or 16 unsigned, or 32 float (pixels then
 * hold the values, converted); `samples` per pixel. */
const char *write_tiff(const char *name, const uint16_t *pixels, uint32_t width, uint32_t height, int bits,
                       int samples, int compression);

/* A little-endian TIFF laid out by hand: 16-bit, one sample, one strip of
 * `strip_bytes` declared bytes, of which `present_bytes` follow (zeros). */
const char *write_raw_tiff(const char *name, uint32_t width, uint32_t height, uint32_t strip_bytes,
                           uint32_t present_bytes);

/* A PNG laid out by hand: signature, a 16-bit gray IHDR of this size, an
 * empty IDAT and IEND (valid CRCs): a header announcing pixels it lacks. */
const char *write_raw_png_header(const char *name, uint32_t width, uint32_t height);

/* The first `size` bytes of the file `from`, as scratch file `name`. */
const char *write_prefix(const char *name, const char *from, size_t size);

/* Size of a file in bytes. */
size_t file_size(const char *path);

#endif /* OPX_TESTS_DEPTH_FILES_H */
