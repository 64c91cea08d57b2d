/*
 * Fuzz target: 16-bit depth images (tools/clouds depth_image_read_file,
 * PNG through libpng and TIFF through libtiff, the format told by the
 * first bytes), the input being the file.  An image that is read must
 * hold width * height pixels within the size limit; a failure must leave
 * the image empty with a message.
 */
#include "fuzz_require.h"
#include "fuzz_file.h"

#include "depth_image.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const char *path = fuzz_scratch_file(".depth", data, size);
    depth_image image;
    char error[256] = "";
    if (depth_image_read_file(path, &image, error, sizeof error) != 0) {
        FUZZ_REQUIRE(image.pixels == NULL && image.width == 0 && image.height == 0);
        FUZZ_REQUIRE(error[0] != '\0');
        return 0;
    }
    const uint64_t pixels = (uint64_t)image.width * image.height;
    FUZZ_REQUIRE(pixels > 0 && pixels <= DEPTH_IMAGE_MAX_PIXELS);
    FUZZ_REQUIRE(image.pixels != NULL);
    uint64_t sum = 0; /* every pixel readable */
    for (uint64_t i = 0; i < pixels; ++i) sum += image.pixels[i];
    FUZZ_REQUIRE(sum <= pixels * 65535u);
    depth_image_free(&image);
    return 0;
}
