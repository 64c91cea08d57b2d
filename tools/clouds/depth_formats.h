/*
 * The format readers behind depth_image_read_file (internal to
 * opx_depth_images).  Each reads an open file positioned at its start and
 * fills *out, or returns -1 with the reason (without the file's name).
 */
#ifndef OPX_CLOUDS_DEPTH_FORMATS_H
#define OPX_CLOUDS_DEPTH_FORMATS_H

#include "depth_image.h"

#include <stdio.h>

int depth_png_read(FILE *file, depth_image *out, char *reason, size_t reason_size);
int depth_tiff_read(FILE *file, depth_image *out, char *reason, size_t reason_size);

/* Checks width x height against the limits and allocates out->pixels for
 * them.  0, or -1 with the reason. */
int depth_image_allocate(depth_image *out, uint64_t width, uint64_t height, char *reason,
                         size_t reason_size);

#endif /* OPX_CLOUDS_DEPTH_FORMATS_H */
