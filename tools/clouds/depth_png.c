/* 16-bit grayscale PNG depth images through libpng. */
#include "cloud_io.h"
#include "depth_formats.h"

#include <png.h>

#include <stdlib.h>
#include <string.h>

/* What the error callback and the reader share: libpng leaves through
 * longjmp, so everything to clean up lives here, not in locals. */
typedef struct png_job {
    png_structp png;
    png_infop info;
    png_bytep *rows;
    char *reason;
    size_t reason_size;
} png_job;

static void on_png_error(png_structp png, png_const_charp message) {
    png_job *job = png_get_error_ptr(png);
    cloud_set_error(job->reason, job->reason_size, "unreadable PNG (corrupt or truncated): %s", message);
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp message) {
    (void)png;
    (void)message; /* e.g. an unknown ancillary chunk: the pixels are still read */
}

static const char *color_name(int color_type) {
    switch (color_type) {
    case PNG_COLOR_TYPE_GRAY: return "grayscale";
    case PNG_COLOR_TYPE_GRAY_ALPHA: return "grayscale with alpha";
    case PNG_COLOR_TYPE_PALETTE: return "palette";
    case PNG_COLOR_TYPE_RGB: return "RGB";
    case PNG_COLOR_TYPE_RGB_ALPHA: return "RGBA";
    default: return "unknown colour type";
    }
}

/* Reads the header, checks the pixel type and allocates the pixels. */
static int read_header(png_job *job, depth_image *out) {
    const png_uint_32 width = png_get_image_width(job->png, job->info);
    const png_uint_32 height = png_get_image_height(job->png, job->info);
    const int bit_depth = png_get_bit_depth(job->png, job->info);
    const int color_type = png_get_color_type(job->png, job->info);
    size_t v;
    if (bit_depth != 16 || color_type != PNG_COLOR_TYPE_GRAY) {
        cloud_set_error(job->reason, job->reason_size, "PNG is %d-bit %s; a depth image is 16-bit grayscale",
                        bit_depth, color_name(color_type));
        return -1;
    }
    if (depth_image_allocate(out, width, height, job->reason, job->reason_size) != 0) return -1;
    job->rows = malloc(out->height * sizeof *job->rows);
    if (job->rows == NULL) {
        cloud_set_error(job->reason, job->reason_size, "out of memory for %u rows", out->height);
        return -1;
    }
    for (v = 0; v < out->height; ++v) job->rows[v] = (png_bytep)(out->pixels + v * out->width);
    return 0;
}

/* The part that may longjmp back (through on_png_error) to the reader. */
static int decode(png_job *job, FILE *file, depth_image *out) {
    const uint16_t one = 1;
    png_init_io(job->png, file);
    png_read_info(job->png, job->info);
    if (read_header(job, out) != 0) return -1;
    if (*(const unsigned char *)&one == 1) png_set_swap(job->png); /* PNG is big-endian */
    png_set_interlace_handling(job->png);
    png_read_update_info(job->png, job->info);
    if (png_get_rowbytes(job->png, job->info) != (size_t)out->width * 2) {
        cloud_set_error(job->reason, job->reason_size, "PNG rows are not %u 16-bit pixels", out->width);
        return -1;
    }
    png_read_image(job->png, job->rows);
    png_read_end(job->png, NULL);
    snprintf(out->format, sizeof out->format, "png 16-bit gray");
    return 0;
}

/* decode, or -1 when libpng gave up on the file (through on_png_error). */
static int guarded_decode(png_job *job, FILE *file, depth_image *out) {
    if (setjmp(png_jmpbuf(job->png)) != 0) return -1;
    return decode(job, file, out);
}

int depth_png_read(FILE *file, depth_image *out, char *reason, size_t reason_size) {
    /* On the heap: the fields change between setjmp and a longjmp, which
     * would leave them indeterminate in a non-volatile local. */
    png_job *const job = calloc(1, sizeof *job);
    int status = -1;
    if (job == NULL) {
        cloud_set_error(reason, reason_size, "out of memory for the PNG reader");
        return -1;
    }
    job->reason = reason;
    job->reason_size = reason_size;
    job->png = png_create_read_struct(PNG_LIBPNG_VER_STRING, job, on_png_error, on_png_warning);
    if (job->png != NULL) job->info = png_create_info_struct(job->png);
    if (job->info == NULL) {
        cloud_set_error(reason, reason_size, "out of memory for the PNG reader");
    } else {
        status = guarded_decode(job, file, out);
    }
    png_destroy_read_struct(&job->png, &job->info, NULL);
    free(job->rows);
    free(job);
    return status;
}
