/* Depth images in `octoprox ingest`: see ingest_depth.h. */
#include "ingest_depth.h"

#include "depth_image.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char kIntrinsicsUsage[] =
    "--intrinsics needs fx,fy,cx,cy (pixels, finite decimal numbers; fx and fy positive)";
static const char kScaleHint[] = "depth units per metre: 1000 for millimetres, 5000 for TUM RGB-D PNGs";

/* "fx,fy,cx,cy": 0, or -1 when malformed. */
static int parse_intrinsics(const char *text, opx_camera_intrinsics *out) {
    double v[4];
    if (cli_parse_numbers(text, v, 4) != 4 || !(v[0] > 0.0 && v[1] > 0.0)) return -1;
    out->fx = v[0], out->fy = v[1], out->cx = v[2], out->cy = v[3];
    return 0;
}

int ingest_camera_option(cli_args *args, ingest_camera *camera) {
    int got;
    if ((got = cli_value(args, "--intrinsics")) != 0) {
        const opx_camera_intrinsics defaults = OPX_CAMERA_INTRINSICS_INIT;
        camera->intrinsics = defaults;
        if (got < 0 || parse_intrinsics(args->value, &camera->intrinsics) != 0)
            return cli_usage("ingest", "%s", kIntrinsicsUsage);
        camera->has_intrinsics = 1;
        return 1;
    }
    if ((got = cli_value(args, "--depth-scale")) != 0) {
        if (got < 0 || cli_parse_double(args->value, &camera->depth_scale) != 0 || !(camera->depth_scale > 0.0))
            return cli_usage("ingest", "--depth-scale needs a positive number (%s)", kScaleHint);
        return 1;
    }
    return 0;
}

int ingest_is_depth_image(const char *path) { return depth_image_file_supported(path); }

int ingest_check_camera(const ingest_camera *camera, const char *const *inputs, int count) {
    const char *image = NULL;
    int i;
    for (i = 0; i < count && image == NULL; ++i)
        if (ingest_is_depth_image(inputs[i])) image = inputs[i];
    if (image == NULL && camera->has_intrinsics)
        return cli_usage("ingest", "--intrinsics is for depth images (.png, .tif, .tiff), and none is given");
    if (image == NULL && camera->depth_scale > 0.0)
        return cli_usage("ingest", "--depth-scale is for depth images (.png, .tif, .tiff), and none is given");
    if (image != NULL && !camera->has_intrinsics)
        return cli_usage("ingest", "the depth image '%s' needs --intrinsics fx,fy,cx,cy (pixels)", image);
    if (image != NULL && !(camera->depth_scale > 0.0))
        return cli_usage("ingest", "the depth image '%s' needs --depth-scale S (%s)", image, kScaleHint);
    return -1;
}

int ingest_depth_file(const char *path, opx_octree *map, const ingest_camera *camera,
                      const opx_insert_options *insert, ingest_result *result) {
    char error[700];
    depth_image pixels;
    opx_depth_image image = OPX_DEPTH_IMAGE_INIT;
    opx_status status;
    double start;
    if (depth_image_read_file(path, &pixels, error, sizeof error) != 0)
        return cli_fail("ingest", CLI_EXIT_INPUT, "%s", error);
    snprintf(result->format, sizeof result->format, "%s", pixels.format);
    result->points = (size_t)pixels.width * pixels.height;
    result->report = (opx_insert_report)OPX_INSERT_REPORT_INIT;
    image.data = pixels.pixels;
    image.width = pixels.width;
    image.height = pixels.height;
    image.depth_scale = camera->depth_scale;
    start = cli_now_ms();
    status = opx_octree_insert_depth_image(map, &image, &camera->intrinsics, insert, &result->report);
    result->insert_ms = cli_now_ms() - start;
    depth_image_free(&pixels);
    return status == OPX_OK ? -1 : cli_library_fail("ingest", status, "inserting %s", path);
}
