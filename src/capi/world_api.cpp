// C shims: worlds of known objects (world.h) and the scene files they are
// read from.
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/shape_input.hpp"
#include "capi/world_handle.hpp"
#include "world/scene_file.hpp"

#include <memory>

using namespace octoprox;
using namespace octoprox::capi;

namespace octoprox::capi {

uint32_t require_object(const opx_world *world, uint32_t object) {
    if (object >= world->world.object_count())
        throw_invalid(format("object %u does not exist (the world has %zu objects)", object,
                             world->world.object_count()));
    return object;
}

void refuse_world(const opx_query *query) {
    if (query != nullptr && query->context.world() != nullptr)
        throw ApiError(OPX_ERROR_UNSUPPORTED, "query has a world set (opx_query_set_world), whose objects this call "
                                              "does not check; set it to NULL for an octree-only call");
}

}  // namespace octoprox::capi

namespace {

opx_pose pose_to_abi(const Pose &pose) {
    const Eigen::Quaterniond q(pose.rotation);
    return opx_pose{{pose.translation.x(), pose.translation.y(), pose.translation.z()}, {q.x(), q.y(), q.z(), q.w()}};
}

// A new world filled by `fill`, handed to the caller only when complete.
template <class Fill>
void make_world(opx_world **out, Fill &&fill) {
    auto world = std::make_unique<opx_world>();
    fill(world->world);
    *out = world.release();
}

}  // namespace

extern "C" {

OPX_API opx_status opx_world_create(opx_world **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(out, "out");
        make_world(out, [](World &) {});
        return OPX_OK;
    });
}

OPX_API void opx_world_destroy(opx_world *world) { delete world; }

OPX_API opx_status opx_world_add_object(opx_world *world, const char *name, const opx_pose *pose,
                                        uint32_t *out_object) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_pointer(name, "name");
        const Pose placed = pose == nullptr ? Pose() : read_pose(*pose, "pose");
        require_position_in_bounds(placed, "pose");
        const uint32_t index = world->world.add_object(name, placed);
        if (out_object != nullptr) *out_object = index;
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_add_shape(opx_world *world, uint32_t object, const opx_shape *shape,
                                       uint32_t *out_shape) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_object(world, object);
        const uint32_t index = world->world.add_shape(object, read_shape(shape));
        if (out_shape != nullptr) *out_shape = index;
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_remove_object(opx_world *world, uint32_t object) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        world->world.remove_object(require_object(world, object));
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_set_object_pose(opx_world *world, uint32_t object, const opx_pose *pose) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_object(world, object);
        require_pointer(pose, "pose");
        const Pose placed = read_pose(*pose, "pose");
        require_position_in_bounds(placed, "pose");
        world->world.set_object_pose(object, placed);
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_get_object_pose(const opx_world *world, uint32_t object, opx_pose *out_pose) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_object(world, object);
        require_pointer(out_pose, "out_pose");
        *out_pose = pose_to_abi(world->world.object(object).pose);
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_set_object_enabled(opx_world *world, uint32_t object, int32_t enabled) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        world->world.set_object_enabled(require_object(world, object), enabled != 0);
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_get_object_enabled(const opx_world *world, uint32_t object, int32_t *out_enabled) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_object(world, object);
        require_pointer(out_enabled, "out_enabled");
        *out_enabled = world->world.object(object).enabled ? 1 : 0;
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_get_object_count(const opx_world *world, uint32_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(world->world.object_count());
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_get_object_name(const opx_world *world, uint32_t object, const char **out_name) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_object(world, object);
        require_pointer(out_name, "out_name");
        *out_name = world->world.object(object).name.c_str();
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_find_object(const opx_world *world, const char *name, uint32_t *out_object) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_pointer(name, "name");
        require_pointer(out_object, "out_object");
        const int64_t found = world->world.find_object(name);
        if (found < 0) throw_invalid(format("no object is named '%s'", name));
        *out_object = static_cast<uint32_t>(found);
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_get_shape_count(const opx_world *world, uint32_t object, uint32_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_object(world, object);
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(world->world.object(object).shapes.size());
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_get_shape(const opx_world *world, uint32_t object, uint32_t shape,
                                       opx_shape *out_shape) {
    return guard(__func__, [&] {
        require_pointer(world, "world");
        require_object(world, object);
        require_out_struct(out_shape, "out_shape");
        const auto &shapes = world->world.object(object).shapes;
        if (shape >= shapes.size())
            throw_invalid(format("shape %u does not exist (object %u has %zu shapes)", shape, object, shapes.size()));
        write_versioned(out_shape, shape_to_abi(*shapes[shape]), "out_shape");
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_load_scene_file(const char *path, opx_world **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(path, "path");
        require_pointer(out, "out");
        make_world(out, [&](World &world) { load_scene_file(path, world); });
        return OPX_OK;
    });
}

OPX_API opx_status opx_world_load_scene_memory(const void *data, size_t size, int32_t format, opx_world **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        if (size > 0) require_pointer(data, "data");
        require_pointer(out, "out");
        if (format != OPX_SCENE_FORMAT_YAML && format != OPX_SCENE_FORMAT_TEXT)
            throw_invalid(octoprox::format("format %d is neither OPX_SCENE_FORMAT_YAML (1) nor OPX_SCENE_FORMAT_TEXT (2)",
                                           format));
        const std::string text = size > 0 ? std::string(static_cast<const char *>(data), size) : std::string();
        const SceneFormat kind = format == OPX_SCENE_FORMAT_YAML ? SceneFormat::kYaml : SceneFormat::kText;
        make_world(out, [&](World &world) { read_scene(text, kind, "data", world); });
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_set_world(opx_query *query, const opx_world *world) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        query->context.set_world(world == nullptr ? nullptr : &world->world);
        return OPX_OK;
    });
}

}  // extern "C"
