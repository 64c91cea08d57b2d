// C shims: loading and saving OctoMap files, memory images and messages.
#include "capi/checks.hpp"
#include "base/atomic_file.h"
#include "base/file_bytes.hpp"
#include "capi/handles.hpp"
#include "octree/octomap_io.hpp"
#include "octree/octoprox_map_io.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <new>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

bool ends_with(const std::string &text, const char *suffix) {
    const size_t n = std::strlen(suffix);
    return text.size() >= n && text.compare(text.size() - n, n, suffix) == 0;
}

// OPX_FORMAT_* to write, from the format or the path's extension.
int32_t save_format(int32_t format, const char *path) {
    if (format == OPX_FORMAT_BT || format == OPX_FORMAT_OT || format == OPX_FORMAT_OPX) return format;
    if (format != OPX_FORMAT_AUTO)
        throw_invalid(octoprox::format("format %d is not OPX_FORMAT_AUTO, _BT, _OT or _OPX", format));
    if (path == nullptr) return OPX_FORMAT_BT;
    const std::string name(path);
    if (ends_with(name, ".bt")) return OPX_FORMAT_BT;
    if (ends_with(name, ".ot")) return OPX_FORMAT_OT;
    if (ends_with(name, ".opx")) return OPX_FORMAT_OPX;
    throw_invalid(octoprox::format("path \"%s\" ends neither in .bt, .ot nor .opx; give the format", path));
}

std::string map_bytes(const SensorOctree &tree, int32_t format) {
    if (format == OPX_FORMAT_OPX) return write_octoprox_map_bytes(tree);
    return write_map_file_bytes(tree, format == OPX_FORMAT_BT ? MapFormat::kBinary : MapFormat::kFull);
}

// An OctoProx map or an OctoMap file, told apart by their first line.
std::unique_ptr<SensorOctree> read_any_map(const std::string &bytes, const OctreeParams &params) {
    return is_octoprox_map(bytes) ? read_octoprox_map_bytes(bytes, params) : read_map_file_bytes(bytes, params);
}

// A map file's first bytes, holding its whole header (OctoMap's takes a few
// lines, OctoProx's first line is then followed by an .ot header).
constexpr size_t kMapHeaderBytes = 65536;

size_t map_size_bound(const std::string &prefix) {
    return is_octoprox_map(prefix) ? octoprox_map_size_bound(prefix) : map_file_size_bound(prefix);
}

// Writes the map whole or not at all (base/atomic_file.h): a fresh
// temporary beside the target, renamed over it; a failed save leaves the
// previous map and no temporary.
void save_map_bytes(const char *path, const std::string &bytes) {
    if (atomic_file_write(path, bytes.data(), bytes.size()) == 0) return;
    const int error = errno;
    if (error == ENOMEM) throw std::bad_alloc();
    throw ApiError(OPX_ERROR_IO, format("cannot write \"%s\": %s", path, std::strerror(error)));
}

opx_status hand_out(std::unique_ptr<SensorOctree> tree, opx_octree **out) {
    auto handle = std::make_unique<opx_octree>();
    handle->tree = std::move(tree);
    *out = handle.release();
    return OPX_OK;
}

}  // namespace

extern "C" {

OPX_API opx_status opx_octree_load_file(const char *path, const opx_octree_options *options,
                                        opx_octree **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(out, "out");
        require_pointer(path, "path");
        const OctreeParams params = read_octree_options(options, "options");
        const std::string bytes = read_bounded_file_bytes(path, "map file", kMapHeaderBytes, map_size_bound);
        return hand_out(read_any_map(bytes, params), out);
    });
}

OPX_API opx_status opx_octree_load_memory(const void *data, size_t size,
                                          const opx_octree_options *options, opx_octree **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(out, "out");
        if (size > 0) require_pointer(data, "data");
        const OctreeParams params = read_octree_options(options, "options");
        const std::string bytes(static_cast<const char *>(data), size);
        return hand_out(read_any_map(bytes, params), out);
    });
}

OPX_API opx_status opx_octree_load_message(const void *data, size_t size, int32_t binary,
                                           double resolution, const opx_octree_options *options,
                                           opx_octree **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(out, "out");
        if (size > 0) require_pointer(data, "data");
        if (!resolution_in_range(resolution))
            throw_invalid(format("resolution is %g; a cell edge from %g to %g metres is needed", resolution,
                                 kMinResolution, kMaxResolution));
        const OctreeParams params = read_octree_options(options, "options");
        const std::string body(static_cast<const char *>(data), size);
        const MapFormat format = binary ? MapFormat::kBinary : MapFormat::kFull;
        return hand_out(read_map_body(body, format, resolution, params), out);
    });
}

OPX_API opx_status opx_octree_save_file(const opx_octree *tree, const char *path, int32_t format) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        require_pointer(path, "path");
        save_map_bytes(path, map_bytes(*tree->tree, save_format(format, path)));
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_save_memory(const opx_octree *tree, int32_t format, void *buffer,
                                          size_t capacity, size_t *out_size) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        require_pointer(out_size, "out_size");
        if (capacity > 0) require_pointer(buffer, "buffer");
        const std::string bytes = map_bytes(*tree->tree, save_format(format, nullptr));
        *out_size = bytes.size();
        if (bytes.size() > capacity)
            throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                           octoprox::format("buffer holds %zu bytes, %zu are needed (see *out_size)", capacity,
                                  bytes.size()));
        std::memcpy(buffer, bytes.data(), bytes.size());
        return OPX_OK;
    });
}

}  // extern "C"
