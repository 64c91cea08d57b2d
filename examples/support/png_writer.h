/* A minimal PNG writer (8-bit RGB, no interlace) over zlib's compress(). */
#ifndef OPX_EXAMPLES_PNG_WRITER_H
#define OPX_EXAMPLES_PNG_WRITER_H

#include <stdint.h>

/* Writes width x height RGB pixels (row-major, 3 bytes each) to path.
 * Returns 0, or -1 when out of memory or the file cannot be written. */
int png_write_rgb(const char *path, const uint8_t *rgb, uint32_t width, uint32_t height);

#endif /* OPX_EXAMPLES_PNG_WRITER_H */
