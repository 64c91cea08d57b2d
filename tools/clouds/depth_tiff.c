/* 16-bit single-channel TIFF depth images through libtiff. */
#define _POSIX_C_SOURCE 200809L

#include "cloud_io.h"
#include "depth_formats.h"

#include <tiffio.h>

#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* The most libtiff may allocate at once (strip buffers, tag arrays) for a
 * file that claims more than it holds. */
#define TIFF_MAX_SINGLE_ALLOC ((tmsize_t)64 << 20)

/* libtiff's first error message, kept for ours (its handlers would print
 * on stderr). */
typedef struct tiff_job {
    char message[256];
} tiff_job;

static int on_tiff_error(TIFF *tif, void *user, const char *module, const char *format, va_list args) {
    tiff_job *job = user;
    (void)tif;
    (void)module;
    if (job->message[0] == '\0') vsnprintf(job->message, sizeof job->message, format, args);
    return 1; /* handled: not passed to the global handler */
}

static int on_tiff_warning(TIFF *tif, void *user, const char *module, const char *format, va_list args) {
    (void)tif, (void)user, (void)module, (void)format, (void)args;
    return 1; /* e.g. an unknown tag: the pixels are still read */
}

/* 16-bit unsigned, one sample, min-is-black (or no photometric tag). */
static int check_pixel_type(TIFF *tif, char *reason, size_t reason_size) {
    uint16_t bits = 0, samples = 0, sample_format = 0, photometric = PHOTOMETRIC_MINISBLACK;
    TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &samples);
    TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &sample_format);
    TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &photometric);
    if (bits != 16 || samples != 1 || sample_format != SAMPLEFORMAT_UINT) {
        cloud_set_error(reason, reason_size,
                        "TIFF has %u-bit %s samples, %u per pixel; a depth image is 16-bit unsigned, one per pixel",
                        (unsigned)bits, sample_format == SAMPLEFORMAT_UINT ? "unsigned" : "signed or float",
                        (unsigned)samples);
        return -1;
    }
    if (photometric != PHOTOMETRIC_MINISBLACK) {
        cloud_set_error(reason, reason_size, "TIFF photometric interpretation %u is not min-is-black grey",
                        (unsigned)photometric);
        return -1;
    }
    if (TIFFIsTiled(tif)) {
        cloud_set_error(reason, reason_size, "tiled TIFF is not supported (strips only)");
        return -1;
    }
    return 0;
}

static int decode(TIFF *tif, const tiff_job *job, depth_image *out, char *reason, size_t reason_size) {
    uint32_t width = 0, height = 0, row;
    if (!TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &width) || !TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &height)) {
        cloud_set_error(reason, reason_size, "TIFF without an image width or length");
        return -1;
    }
    if (check_pixel_type(tif, reason, reason_size) != 0) return -1;
    if (depth_image_allocate(out, width, height, reason, reason_size) != 0) return -1;
    if (TIFFScanlineSize64(tif) != (uint64_t)width * 2) {
        cloud_set_error(reason, reason_size, "TIFF rows are not %u 16-bit pixels", width);
        return -1;
    }
    for (row = 0; row < height; ++row) {
        if (TIFFReadScanline(tif, out->pixels + (size_t)row * width, row, 0) < 0) {
            cloud_set_error(reason, reason_size, "unreadable TIFF (corrupt or truncated) at row %u: %s", row,
                            job->message);
            return -1;
        }
    }
    snprintf(out->format, sizeof out->format, "tiff 16-bit gray");
    return 0;
}

/* libtiff reads through its own descriptor (a duplicate: TIFFClose
 * closes it, the caller closes the FILE). */
static TIFF *open_tiff(FILE *file, tiff_job *job) {
    TIFFOpenOptions *options = TIFFOpenOptionsAlloc();
    TIFF *tif = NULL;
    int fd;
    if (options == NULL) return NULL;
    TIFFOpenOptionsSetErrorHandlerExtR(options, on_tiff_error, job);
    TIFFOpenOptionsSetWarningHandlerExtR(options, on_tiff_warning, job);
    TIFFOpenOptionsSetMaxSingleMemAlloc(options, TIFF_MAX_SINGLE_ALLOC);
    fd = dup(fileno(file));
    if (fd >= 0) {
        tif = TIFFFdOpenExt(fd, "depth image", "r", options);
        if (tif == NULL) close(fd);
    }
    TIFFOpenOptionsFree(options);
    return tif;
}

int depth_tiff_read(FILE *file, depth_image *out, char *reason, size_t reason_size) {
    tiff_job job;
    TIFF *tif;
    int status;
    memset(&job, 0, sizeof job);
    tif = open_tiff(file, &job);
    if (tif == NULL) {
        cloud_set_error(reason, reason_size, "unreadable TIFF (corrupt or truncated): %s",
                        job.message[0] != '\0' ? job.message : "cannot open");
        return -1;
    }
    status = decode(tif, &job, out, reason, reason_size);
    TIFFClose(tif);
    return status;
}
