// C shims: point clouds read from PCD and PLY files by the C readers of
// clouds/ (the ones the octoprox tool uses).
#include "capi/checks.hpp"

#include <octoprox/io.h>

#include "clouds/cloud_file.h"

#include <cstring>
#include <memory>

struct opx_point_cloud {
    cloud_points cloud{};
    ~opx_point_cloud() { cloud_free(&cloud); }
};

namespace octoprox::capi {
namespace {

opx_status status_of(int reader_status) {
    switch (reader_status) {
    case CLOUD_ERROR_IO: return OPX_ERROR_IO;
    case CLOUD_ERROR_NO_MEMORY: return OPX_ERROR_OUT_OF_MEMORY;
    case CLOUD_ERROR_UNSUPPORTED: return OPX_ERROR_UNSUPPORTED;
    case CLOUD_ERROR_INVALID: return OPX_ERROR_INVALID_ARGUMENT;
    default: return OPX_ERROR_CORRUPT;
    }
}

int32_t encoding_of(const cloud_points &cloud) {
    if (std::strcmp(cloud.encoding, "ascii") == 0) return OPX_CLOUD_ENCODING_ASCII;
    if (std::strcmp(cloud.encoding, "binary_compressed") == 0) return OPX_CLOUD_ENCODING_BINARY_COMPRESSED;
    return OPX_CLOUD_ENCODING_BINARY;
}

// PCD order tx ty tz qw qx qy qz to ROS order x y z qx qy qz qw.
opx_pose viewpoint_pose(const double viewpoint[7]) {
    return opx_pose{{viewpoint[0], viewpoint[1], viewpoint[2]},
                    {viewpoint[4], viewpoint[5], viewpoint[6], viewpoint[3]}};
}

opx_point_cloud_info info_of(const cloud_points &cloud) {
    opx_point_cloud_info info = OPX_POINT_CLOUD_INFO_INIT;
    info.format = cloud.kind == CLOUD_FILE_PCD ? OPX_CLOUD_FORMAT_PCD : OPX_CLOUD_FORMAT_PLY;
    info.encoding = encoding_of(cloud);
    info.has_viewpoint = cloud.has_viewpoint;
    info.point_count = cloud.count;
    info.finite_count = cloud.finite_count;
    info.width = cloud.width;
    info.height = cloud.height;
    info.viewpoint = viewpoint_pose(cloud.viewpoint);
    return info;
}

// The byte step between output points, checked.
size_t point_step(size_t stride) {
    constexpr size_t kPacked = 3 * sizeof(float);
    if (stride == 0) return kPacked;
    if (stride < kPacked || stride % sizeof(float) != 0)
        throw_invalid(format("stride %zu is neither 0 (packed) nor a multiple of 4 bytes of at least 12 "
                             "(x y z float32)",
                             stride));
    return stride;
}

}  // namespace
}  // namespace octoprox::capi

using namespace octoprox;
using namespace octoprox::capi;

extern "C" {

OPX_API opx_status opx_point_cloud_info_init(opx_point_cloud_info *info, size_t size) {
    return init_struct(__func__, info, size, opx_point_cloud_info(OPX_POINT_CLOUD_INFO_INIT), "info");
}

OPX_API opx_status opx_point_cloud_read_file(const char *path, opx_point_cloud **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(path, "path");
        require_pointer(out, "out");
        auto cloud = std::make_unique<opx_point_cloud>();
        char error[1024] = "";
        const int status = cloud_read_file(path, &cloud->cloud, error, sizeof error);
        if (status != 0) throw ApiError(status_of(status), format("path %s", error));
        *out = cloud.release();
        return OPX_OK;
    });
}

OPX_API void opx_point_cloud_destroy(opx_point_cloud *cloud) { delete cloud; }

OPX_API opx_status opx_point_cloud_get_info(const opx_point_cloud *cloud, opx_point_cloud_info *out) {
    return guard(__func__, [&] {
        require_pointer(cloud, "cloud");
        write_versioned(out, info_of(cloud->cloud), "out");
        return OPX_OK;
    });
}

OPX_API opx_status opx_point_cloud_get_points(const opx_point_cloud *cloud, float *out_xyz, size_t capacity,
                                              size_t stride, size_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(cloud, "cloud");
        require_pointer(out_count, "out_count");
        const size_t step = point_step(stride), count = cloud->cloud.count;
        *out_count = count;
        if (capacity < count)
            throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                           format("capacity %zu is smaller than the point count %zu", capacity, count));
        if (count > 0) require_pointer(out_xyz, "out_xyz");
        unsigned char *at = reinterpret_cast<unsigned char *>(out_xyz);
        for (size_t i = 0; i < count; ++i) std::memcpy(at + i * step, &cloud->cloud.xyz[3 * i], 3 * sizeof(float));
        return OPX_OK;
    });
}

}  // extern "C"
