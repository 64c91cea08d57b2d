/*
 * depth_readers: the octoprox tool's depth image readers on files written
 * here: 16-bit PNG and TIFF (uncompressed, PackBits) read back exactly,
 * the format told by the first bytes, and bad files (other bit depths and
 * channel counts, float samples, truncated data, headers announcing far
 * more pixels than allowed, files of neither format) refused with a
 * message naming the file, nothing allocated.
 */
#define _POSIX_C_SOURCE 200809L

#include "cli_run.h"
#include "depth_files.h"
#include "depth_image.h"

#include <tiffio.h>

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include <cmocka.h>

#define W 7
#define H 5

static uint16_t g_pixels[H * W * 3];

static void make_pixels(void) {
    int i;
    for (i = 0; i < H * W * 3; ++i) g_pixels[i] = (uint16_t)(i * 977 % 65536);
    g_pixels[0] = 0;
    g_pixels[1] = 65535;
    g_pixels[2] = 256; /* a byte-order mistake would read 1 */
}

static void expect_pixels(const char *path, const char *format) {
    depth_image image;
    char error[700] = "";
    if (depth_image_read_file(path, &image, error, sizeof error) != 0) fail_msg("%s", error);
    assert_int_equal(image.width, W);
    assert_int_equal(image.height, H);
    assert_string_equal(image.format, format);
    assert_memory_equal(image.pixels, g_pixels, sizeof(uint16_t) * W * H);
    depth_image_free(&image);
    assert_null(image.pixels);
}

static void expect_error(const char *path, const char *message) {
    depth_image image;
    char error[700] = "";
    if (depth_image_read_file(path, &image, error, sizeof error) == 0)
        fail_msg("%s was read (%u x %u)", path, image.width, image.height);
    if (strstr(error, message) == NULL) fail_msg("%s: \"%s\" lacks \"%s\"", path, error, message);
    if (strstr(error, path) == NULL) fail_msg("\"%s\" does not name the file %s", error, path);
    assert_null(image.pixels);
    assert_int_equal(image.width, 0);
}

static void png_and_tiff_read_back_exactly(void **state) {
    (void)state;
    expect_pixels(write_png("gray16.png", g_pixels, W, H, 16, 1), "png 16-bit gray");
    expect_pixels(write_tiff("plain.tiff", g_pixels, W, H, 16, 1, COMPRESSION_NONE), "tiff 16-bit gray");
    expect_pixels(write_tiff("packbits.tif", g_pixels, W, H, 16, 1, COMPRESSION_PACKBITS), "tiff 16-bit gray");
}

/* The first bytes, not the name, tell the format. */
static void the_format_comes_from_the_content(void **state) {
    (void)state;
    expect_pixels(write_tiff("tiff_named.png", g_pixels, W, H, 16, 1, COMPRESSION_NONE), "tiff 16-bit gray");
    expect_pixels(write_png("png_named.tiff", g_pixels, W, H, 16, 1), "png 16-bit gray");
    expect_error(write_text("text.png", "P2\n7 5\n65535\n"), "neither a PNG nor a TIFF");
    expect_error(write_bytes("empty.tif", "", 0), "neither a PNG nor a TIFF");
    expect_error(scratch_path("missing.png"), "cannot open");
    assert_int_equal(depth_image_file_supported("a/b.PNG"), 1);
    assert_int_equal(depth_image_file_supported("b.tif"), 1);
    assert_int_equal(depth_image_file_supported("b.Tiff"), 1);
    assert_int_equal(depth_image_file_supported("b.pgm"), 0);
    assert_int_equal(depth_image_file_supported("png"), 0);
}

static void other_pixel_types_are_refused(void **state) {
    uint16_t bytes[H * W * 3];
    int i;
    (void)state;
    for (i = 0; i < H * W * 3; ++i) bytes[i] = (uint16_t)(g_pixels[i] & 0xff);
    expect_error(write_png("gray8.png", bytes, W, H, 8, 1), "8-bit grayscale");
    expect_error(write_png("rgb16.png", g_pixels, W, H, 16, 3), "16-bit RGB");
    expect_error(write_tiff("gray8.tiff", bytes, W, H, 8, 1, COMPRESSION_NONE), "8-bit unsigned");
    expect_error(write_tiff("rgb16.tiff", g_pixels, W, H, 16, 3, COMPRESSION_NONE), "3 per pixel");
    expect_error(write_tiff("float.tiff", g_pixels, W, H, 32, 1, COMPRESSION_NONE), "float");
}

static void truncated_files_are_refused(void **state) {
    const char *png, *tiff;
    (void)state;
    png = write_png("whole.png", g_pixels, W, H, 16, 1);
    expect_error(write_prefix("half.png", png, file_size(png) / 2), "unreadable PNG");
    expect_error(write_prefix("signature.png", png, 8), "unreadable PNG");
    tiff = write_tiff("whole.tiff", g_pixels, W, H, 16, 1, COMPRESSION_NONE);
    expect_error(write_prefix("half.tiff", tiff, file_size(tiff) / 2), "unreadable TIFF");
    expect_error(write_prefix("header.tiff", tiff, 4), "unreadable TIFF");
    /* The directory is whole, the pixel data short. */
    expect_error(write_raw_tiff("short_strip.tiff", W, H, 2 * W * H, 10), "unreadable TIFF");
}

/* Headers announcing 20000 x 20000 pixels in a file of a few bytes: refused
 * before anything is allocated for them. */
static void huge_headers_are_refused(void **state) {
    (void)state;
    expect_error(write_raw_png_header("huge.png", 20000, 20000), "more than");
    expect_error(write_raw_tiff("huge.tiff", 20000, 20000, 800000000u, 16), "more than");
    expect_error(write_raw_tiff("wide.tiff", 4000000000u, 1, 8000000u, 16), "more than");
    expect_error(write_raw_png_header("zero.png", 0, 5), "unreadable PNG");
    expect_error(write_raw_tiff("zero.tiff", 0, 5, 0, 0), "TIFF");
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(png_and_tiff_read_back_exactly),
        cmocka_unit_test(the_format_comes_from_the_content),
        cmocka_unit_test(other_pixel_types_are_refused),
        cmocka_unit_test(truncated_files_are_refused),
        cmocka_unit_test(huge_headers_are_refused),
    };
    make_pixels();
    return cmocka_run_group_tests_name("depth_readers", tests, NULL, NULL);
}
