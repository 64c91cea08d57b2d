// C shims: depth images back-projected through a pinhole camera into the
// points a sensor frame insert takes.
#include "capi/checks.hpp"
#include "capi/handles.hpp"

#include <cfloat>
#include <cstdint>
#include <limits>
#include <vector>

namespace octoprox::capi {
namespace {

// A caller's depth image, checked: every byte it spans is addressable.
struct DepthFrame {
    const unsigned char *data = nullptr;
    size_t width = 0, height = 0;
    size_t row_step = 0;  // bytes, never 0 for a non-empty image
    bool is_float = false;
    double units_per_metre = 1.0;  // uint16 only

    bool empty() const { return width == 0 || height == 0; }
};

struct Pinhole {
    double fx, fy, cx, cy;
};

size_t pixel_bytes(bool is_float) { return is_float ? sizeof(float) : sizeof(uint16_t); }

// The rows' geometry: a row holds its pixels, the rows fit in the address
// space, and the back-projected points fit in a float buffer.
void check_layout(const opx_depth_image &image, size_t pixel, DepthFrame &frame) {
    if (image.width > SIZE_MAX / pixel)
        throw_invalid(format("image.width %zu pixels span more bytes than memory has", image.width));
    const size_t row_bytes = image.width * pixel;
    if (image.row_stride != 0 && image.row_stride < row_bytes)
        throw_invalid(format("image.row_stride %zu is smaller than one row (%zu pixels of %zu bytes "
                             "= %zu bytes)",
                             image.row_stride, image.width, pixel, row_bytes));
    frame.row_step = image.row_stride == 0 ? row_bytes : image.row_stride;
    if (frame.empty()) return;
    require_pointer(image.data, "image.data");
    if (image.height - 1 > (SIZE_MAX - row_bytes) / frame.row_step)
        throw_invalid(format("image.height %zu rows of %zu bytes span more bytes than memory has",
                             image.height, frame.row_step));
    if (image.width > SIZE_MAX / (3 * sizeof(float)) / image.height)
        throw_invalid(format("image.width * image.height (%zu x %zu) is more pixels than memory "
                             "holds as points",
                             image.width, image.height));
}

DepthFrame read_depth_image(const opx_depth_image *image) {
    require_pointer(image, "image");
    opx_depth_image merged = OPX_DEPTH_IMAGE_INIT;
    read_versioned(image, merged, "image");
    if (merged.scalar_type != OPX_SCALAR_UINT16 && merged.scalar_type != OPX_SCALAR_FLOAT32)
        throw_invalid(format("image.scalar_type %d is neither OPX_SCALAR_UINT16 (3) nor "
                             "OPX_SCALAR_FLOAT32 (1)",
                             merged.scalar_type));
    DepthFrame frame;
    frame.is_float = merged.scalar_type == OPX_SCALAR_FLOAT32;
    frame.width = merged.width;
    frame.height = merged.height;
    check_layout(merged, pixel_bytes(frame.is_float), frame);
    if (!frame.is_float && !(std::isfinite(merged.depth_scale) && merged.depth_scale > 0.0))
        throw_invalid(format("image.depth_scale is %g; a uint16 image needs a positive number of "
                             "depth units per metre (1000 for millimetres)",
                             merged.depth_scale));
    frame.data = static_cast<const unsigned char *>(merged.data);
    frame.units_per_metre = merged.depth_scale;
    return frame;
}

void require_focal_length(double value, const char *argument) {
    if (!(std::isfinite(value) && value > 0.0))
        throw_invalid(format("%s is %g; a focal length is a positive number of pixels", argument, value));
}

Pinhole read_intrinsics(const opx_camera_intrinsics *intrinsics) {
    require_pointer(intrinsics, "intrinsics");
    opx_camera_intrinsics merged = OPX_CAMERA_INTRINSICS_INIT;
    read_versioned(intrinsics, merged, "intrinsics");
    require_focal_length(merged.fx, "intrinsics.fx");
    require_focal_length(merged.fy, "intrinsics.fy");
    require_finite(merged.cx, "intrinsics.cx");
    require_finite(merged.cy, "intrinsics.cy");
    return Pinhole{merged.fx, merged.fy, merged.cx, merged.cy};
}

// Depth in metres of the pixel at `pixel`; 0 when it holds no return.
double depth_at(const DepthFrame &frame, const unsigned char *pixel) {
    if (frame.is_float) {
        float z;
        std::memcpy(&z, pixel, sizeof z);
        return z > 0.0f && z <= FLT_MAX ? z : 0.0;  // NaN, infinity, 0 and below: none
    }
    uint16_t units;
    std::memcpy(&units, pixel, sizeof units);
    return units / frame.units_per_metre;
}

// double to float; a value beyond float's range becomes an infinity (the
// insert counts it as non-finite) instead of an undefined conversion.
float to_float(double value) {
    if (std::fabs(value) <= FLT_MAX) return static_cast<float>(value);
    return value > 0.0 ? std::numeric_limits<float>::infinity() : -std::numeric_limits<float>::infinity();
}

// Packed float x y z of every pixel with a return (optical frame); the
// others are counted in no_return.  All of it is allocated up front.
std::vector<float> back_project(const DepthFrame &frame, const Pinhole &k, uint64_t &no_return) {
    std::vector<float> xyz;
    xyz.reserve(frame.width * frame.height * 3);
    const size_t pixel = pixel_bytes(frame.is_float);
    for (size_t v = 0; v < frame.height; ++v) {
        const unsigned char *row = frame.data + v * frame.row_step;
        const double dy = static_cast<double>(v) - k.cy;
        for (size_t u = 0; u < frame.width; ++u) {
            const double z = depth_at(frame, row + u * pixel);
            if (z == 0.0) {
                ++no_return;
                continue;
            }
            xyz.push_back(to_float((static_cast<double>(u) - k.cx) * z / k.fx));
            xyz.push_back(to_float(dy * z / k.fy));
            xyz.push_back(to_float(z));
        }
    }
    return xyz;
}

}  // namespace
}  // namespace octoprox::capi

using namespace octoprox;
using namespace octoprox::capi;

extern "C" {

OPX_API opx_status opx_depth_image_init(opx_depth_image *image, size_t size) {
    return init_struct(__func__, image, size, opx_depth_image(OPX_DEPTH_IMAGE_INIT), "image");
}

OPX_API opx_status opx_camera_intrinsics_init(opx_camera_intrinsics *intrinsics, size_t size) {
    return init_struct(__func__, intrinsics, size,
                       opx_camera_intrinsics(OPX_CAMERA_INTRINSICS_INIT), "intrinsics");
}

OPX_API opx_status opx_octree_insert_depth_image(opx_octree *tree, const opx_depth_image *image,
                                                 const opx_camera_intrinsics *intrinsics,
                                                 const opx_insert_options *options,
                                                 opx_insert_report *out_report) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        if (out_report != nullptr) require_struct_size(out_report->struct_size, "out_report");
        const DepthFrame frame = read_depth_image(image);
        const Pinhole camera = read_intrinsics(intrinsics);
        const InsertRequest request = read_insert_options(options);
        opx_insert_report report = OPX_INSERT_REPORT_INIT;
        if (!frame.empty()) {
            uint64_t no_return = 0;
            const std::vector<float> xyz = back_project(frame, camera, no_return);
            PointSource source;
            source.data = reinterpret_cast<const unsigned char *>(xyz.data());
            source.count = xyz.size() / 3;
            source.stride = 3 * sizeof(float);
            report = report_from_counts(run_insert(*tree->tree, source, request));
            report.pixels_no_return = no_return;
        }
        if (out_report != nullptr) write_versioned(out_report, report, "out_report");
        return OPX_OK;
    });
}

}  // extern "C"
