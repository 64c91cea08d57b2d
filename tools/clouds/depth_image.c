/* Depth images from PNG and TIFF files: see depth_image.h. */
#include "depth_image.h"
#include "file_extension.h"

#include "cloud_io.h"
#include "depth_formats.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

static const unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

int depth_image_file_supported(const char *path) {
    return path != NULL &&
           (file_has_extension(path, ".png") || file_has_extension(path, ".tif") || file_has_extension(path, ".tiff"));
}

/* Classic and BigTIFF headers, either byte order. */
static int is_tiff(const unsigned char *magic) {
    return (magic[0] == 'I' && magic[1] == 'I' && (magic[2] == 42 || magic[2] == 43) && magic[3] == 0) ||
           (magic[0] == 'M' && magic[1] == 'M' && magic[2] == 0 && (magic[3] == 42 || magic[3] == 43));
}

static int read_any(FILE *file, void *out, char *reason, size_t reason_size) {
    unsigned char magic[8];
    const size_t got = fread(magic, 1, sizeof magic, file);
    if (fseek(file, 0, SEEK_SET) != 0) {
        cloud_set_error(reason, reason_size, "cannot seek (not a regular file?)");
        return -1;
    }
    if (got == sizeof magic && memcmp(magic, kPngSignature, sizeof magic) == 0)
        return depth_png_read(file, out, reason, reason_size);
    if (got >= 4 && is_tiff(magic)) return depth_tiff_read(file, out, reason, reason_size);
    cloud_set_error(reason, reason_size, "neither a PNG nor a TIFF file");
    return -1;
}

int depth_image_read_file(const char *path, depth_image *out, char *error, size_t error_size) {
    memset(out, 0, sizeof *out);
    if (cloud_read_path(path, read_any, out, error, error_size) == 0) return 0;
    depth_image_free(out);
    return -1;
}

int depth_image_allocate(depth_image *out, uint64_t width, uint64_t height, char *reason,
                         size_t reason_size) {
    if (width == 0 || height == 0) {
        cloud_set_error(reason, reason_size, "the image is empty (%llu x %llu pixels)",
                        (unsigned long long)width, (unsigned long long)height);
        return -1;
    }
    if (width > UINT32_MAX || height > UINT32_MAX || width * height > DEPTH_IMAGE_MAX_PIXELS) {
        cloud_set_error(reason, reason_size, "%llu x %llu pixels is more than the %llu a depth image may have",
                        (unsigned long long)width, (unsigned long long)height,
                        (unsigned long long)DEPTH_IMAGE_MAX_PIXELS);
        return -1;
    }
    out->pixels = malloc((size_t)(width * height) * sizeof *out->pixels);
    if (out->pixels == NULL) {
        cloud_set_error(reason, reason_size, "out of memory for %llu x %llu pixels",
                        (unsigned long long)width, (unsigned long long)height);
        return -1;
    }
    out->width = (uint32_t)width;
    out->height = (uint32_t)height;
    return 0;
}

void depth_image_free(depth_image *image) {
    if (image == NULL) return;
    free(image->pixels);
    memset(image, 0, sizeof *image);
}
