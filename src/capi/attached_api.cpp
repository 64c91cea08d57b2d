// C shims: objects attached to links (linkset.h, world.h).
#include "capi/robot_inputs.hpp"
#include "capi/shape_input.hpp"
#include "capi/world_handle.hpp"

#include <octoprox/linkset.h>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

uint32_t require_link(const opx_linkset *links, uint32_t link, const char *argument) {
    if (link >= links->links.link_count())
        throw_invalid(format("%s %u does not exist (the set has %zu links)", argument, link,
                             links->links.link_count()));
    return link;
}

uint32_t require_attached(const opx_linkset *links, uint32_t object) {
    if (object >= links->links.attached_count())
        throw_invalid(format("object %u does not exist (the set has %zu attached objects)", object,
                             links->links.attached_count()));
    return object;
}

// Each name the first link of that name.
std::vector<uint32_t> read_touch_links(const opx_linkset *links, const char *const *names, size_t count) {
    std::vector<uint32_t> out;
    if (count == 0) return out;
    require_pointer(names, "touch_links");
    for (size_t i = 0; i < count; ++i) {
        if (names[i] == nullptr) throw_invalid(format("touch_links[%zu] is NULL", i));
        uint32_t found = 0;
        while (found < links->links.link_count() && links->links.link(found).name != names[i]) ++found;
        if (found == links->links.link_count())
            throw_invalid(format("touch_links[%zu] \"%s\" names no link of the set", i, names[i]));
        out.push_back(found);
    }
    return out;
}

// The caller's shapes, each checked; an error names the element.
std::vector<ShapeDef> read_shapes(const opx_shape *shapes, size_t count) {
    if (count == 0) throw_invalid("shape_count is 0; an attached object needs at least one shape");
    require_pointer(shapes, "shapes");
    std::vector<ShapeDef> out;
    for (size_t i = 0; i < count; ++i) {
        try {
            out.push_back(read_shape(&shapes[i]));
        } catch (const ApiError &e) {
            throw ApiError(e.status(), format("shapes[%zu]: %s", i, e.what()));
        }
    }
    return out;
}

// `inner` seen from `outer` (both in one frame): outer^-1 * inner.
Pose relative(const Pose &outer, const Pose &inner) {
    Pose out;
    out.rotation = outer.rotation.transpose() * inner.rotation;
    out.translation = outer.rotation.transpose() * (inner.translation - outer.translation);
    return out;
}

}  // namespace

extern "C" {

OPX_API opx_status opx_linkset_attach_object(opx_linkset *links, uint32_t link, const char *name,
                                             const opx_shape *shapes, size_t shape_count, const opx_pose *pose,
                                             const char *const *touch_links, size_t touch_link_count,
                                             uint32_t *out_object) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_link(links, link, "link");
        require_pointer(name, "name");
        std::vector<ShapeDef> defs = read_shapes(shapes, shape_count);
        const Pose in_link = pose == nullptr ? Pose() : read_pose(*pose, "pose");
        std::vector<uint32_t> touching = read_touch_links(links, touch_links, touch_link_count);
        const uint32_t index = links->links.attach(name, link, in_link, std::move(defs), std::move(touching));
        if (out_object != nullptr) *out_object = index;
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_attach_world_object(opx_linkset *links, uint32_t link, const opx_world *world,
                                                   uint32_t object, const char *const *touch_links,
                                                   size_t touch_link_count, uint32_t *out_attached) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_link(links, link, "link");
        require_pointer(world, "world");
        const WorldObject &source = world->world.object(require_object(world, object));
        if (source.shapes.empty()) throw_invalid(format("object %u of the world has no shapes", object));
        std::vector<ShapeDef> defs;
        for (const auto &def : source.shapes) defs.push_back(*def);
        std::vector<uint32_t> touching = read_touch_links(links, touch_links, touch_link_count);
        const Pose in_link = relative(links->links.link(link).pose, source.pose);
        const uint32_t index = links->links.attach(source.name, link, in_link, std::move(defs), std::move(touching));
        if (out_attached != nullptr) *out_attached = index;
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_detach_object(opx_linkset *links, uint32_t object) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        links->links.detach(require_attached(links, object));
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_attached_count(const opx_linkset *links, uint32_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(links->links.attached_count());
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_find_attached(const opx_linkset *links, const char *name, uint32_t *out_object) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(name, "name");
        require_pointer(out_object, "out_object");
        const int64_t found = links->links.find_attached(name);
        if (found < 0) throw_invalid(format("no attached object is named \"%s\"", name));
        *out_object = static_cast<uint32_t>(found);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_attached_name(const opx_linkset *links, uint32_t object, const char **out_name) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_name, "out_name");
        *out_name = links->links.attached(require_attached(links, object)).name.c_str();
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_attached_link(const opx_linkset *links, uint32_t object, uint32_t *out_link) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_link, "out_link");
        *out_link = links->links.attached(require_attached(links, object)).link;
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_attached_pose(const opx_linkset *links, uint32_t object, opx_pose *out_pose) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_pose, "out_pose");
        *out_pose = pose_to_abi(links->links.attached(require_attached(links, object)).pose);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_attached_shape_count(const opx_linkset *links, uint32_t object,
                                                        uint32_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(links->links.attached(require_attached(links, object)).shapes.size());
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_attached_shape(const opx_linkset *links, uint32_t object, uint32_t shape,
                                                  opx_shape *out_shape) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        const AttachedObject &a = links->links.attached(require_attached(links, object));
        require_out_struct(out_shape, "out_shape");
        if (shape >= a.shapes.size())
            throw_invalid(format("shape %u does not exist (object %u has %zu shapes)", shape, object, a.shapes.size()));
        opx_shape out = shape_to_abi(*a.shapes[shape]);
        out.pose = pose_to_abi(a.shape_poses[shape]);  // stored in the link frame, given in the object's
        write_versioned(out_shape, out, "out_shape");
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_attached_touch_links(const opx_linkset *links, uint32_t object,
                                                        uint32_t *out_links, size_t capacity, size_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        copy_list_out(links->links.attached(require_attached(links, object)).touch_links, out_links, capacity,
                      out_count, "out_links", "touch link count");
        return OPX_OK;
    });
}

}  // extern "C"
