// C shims: link sets (robots made of shapes).
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/shape_input.hpp"

using namespace octoprox;
using namespace octoprox::capi;

namespace {

uint32_t require_link(const opx_linkset *links, uint32_t link) {
    if (link >= links->links.link_count())
        throw_invalid(format("link %u does not exist (the set has %zu links)", link, links->links.link_count()));
    return link;
}

// The accessors, shared by their opx_linkset_get_* names and the aliases
// (each error names the function the caller called).
opx_status link_count(const char *function, const opx_linkset *links, uint32_t *out_count) {
    return guard(function, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(links->links.link_count());
        return OPX_OK;
    });
}

opx_status shape_count(const char *function, const opx_linkset *links, uint32_t link, uint32_t *out_count) {
    return guard(function, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(links->links.link(require_link(links, link)).shapes.size());
        return OPX_OK;
    });
}

opx_status link_name(const char *function, const opx_linkset *links, uint32_t link, const char **out_name) {
    return guard(function, [&] {
        require_pointer(links, "links");
        require_pointer(out_name, "out_name");
        *out_name = links->links.link(require_link(links, link)).name.c_str();
        return OPX_OK;
    });
}

}  // namespace

extern "C" {

OPX_API opx_status opx_shape_init(opx_shape *shape, size_t size) {
    return init_struct(__func__, shape, size, opx_shape(OPX_SHAPE_INIT), "shape");
}

OPX_API opx_status opx_linkset_create(opx_linkset **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(out, "out");
        *out = new opx_linkset();
        return OPX_OK;
    });
}

OPX_API void opx_linkset_destroy(opx_linkset *links) { delete links; }

OPX_API opx_status opx_linkset_clone(const opx_linkset *links, opx_linkset **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out, "out");
        *out = new opx_linkset{links->links, links->robot, {}};
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_add_link(opx_linkset *links, const char *name, uint32_t *out_link) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(name, "name");
        const uint32_t index = links->links.add_link(name);
        if (out_link != nullptr) *out_link = index;
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_add_shape(opx_linkset *links, uint32_t link, const opx_shape *shape,
                                         uint32_t *out_shape) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_link(links, link);
        const uint32_t index = links->links.add_shape(link, read_shape(shape));
        if (out_shape != nullptr) *out_shape = index;
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_link_count(const opx_linkset *links, uint32_t *out_count) {
    return link_count(__func__, links, out_count);
}

OPX_API opx_status opx_linkset_get_shape_count(const opx_linkset *links, uint32_t link, uint32_t *out_count) {
    return shape_count(__func__, links, link, out_count);
}

OPX_API opx_status opx_linkset_get_link_name(const opx_linkset *links, uint32_t link, const char **out_name) {
    return link_name(__func__, links, link, out_name);
}

OPX_API opx_status opx_linkset_find_link(const opx_linkset *links, const char *name, uint32_t *out_link) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(name, "name");
        require_pointer(out_link, "out_link");
        for (uint32_t i = 0; i < links->links.link_count(); ++i) {
            if (links->links.link(i).name == name) {
                *out_link = i;
                return OPX_OK;
            }
        }
        throw_invalid(format("name \"%.80s\": no link has this name", name));
    });
}

OPX_API opx_status opx_linkset_set_padding(opx_linkset *links, double padding) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_padding(padding, "padding");
        links->links.set_padding(padding);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_set_link_padding(opx_linkset *links, uint32_t link, double padding) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_link(links, link);
        require_padding(padding, "padding");
        links->links.set_link_padding(link, padding);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_set_link_enabled(opx_linkset *links, uint32_t link, int32_t enabled) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_link(links, link);
        links->links.set_link_enabled(link, enabled != 0);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_set_poses(opx_linkset *links, const opx_pose *poses, size_t count,
                                         size_t stride) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        if (count != links->links.link_count())
            throw_invalid(format("count %zu differs from the number of links, %zu", count,
                                 links->links.link_count()));
        if (stride != 0 && stride < sizeof(opx_pose))
            throw_invalid(format("stride %zu is smaller than one opx_pose (%zu bytes)", stride, sizeof(opx_pose)));
        if (count > 0) require_pointer(poses, "poses");
        const size_t step = stride == 0 ? sizeof(opx_pose) : stride;
        std::vector<Pose> &converted = links->pose_scratch;
        converted.resize(count);
        for (size_t i = 0; i < count; ++i) {
            opx_pose pose;
            std::memcpy(&pose, reinterpret_cast<const unsigned char *>(poses) + i * step, sizeof pose);
            converted[i] = read_pose_lazily(pose, [i] { return format("poses[%zu]", i); });
        }
        links->links.set_poses(converted);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_pose(const opx_linkset *links, uint32_t link, opx_pose *out_pose) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_pose, "out_pose");
        const Pose &pose = links->links.link(require_link(links, link)).pose;
        const Eigen::Quaterniond q(pose.rotation);
        *out_pose = opx_pose{{pose.translation.x(), pose.translation.y(), pose.translation.z()},
                             {q.x(), q.y(), q.z(), q.w()}};
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_shape(const opx_linkset *links, uint32_t link, uint32_t shape,
                                         opx_shape *out_shape) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        const auto &shapes = links->links.link(require_link(links, link)).shapes;
        if (shape >= shapes.size())
            throw_invalid(format("shape %u does not exist (link %u has %zu shapes)", shape, link, shapes.size()));
        write_versioned(out_shape, shape_to_abi(*shapes[shape]), "out_shape");
        return OPX_OK;
    });
}

// Aliases of the opx_linkset_get_* accessors, kept for compatibility.
OPX_API opx_status opx_linkset_link_count(const opx_linkset *links, uint32_t *out_count) {
    return link_count(__func__, links, out_count);
}

OPX_API opx_status opx_linkset_shape_count(const opx_linkset *links, uint32_t link, uint32_t *out_count) {
    return shape_count(__func__, links, link, out_count);
}

OPX_API opx_status opx_linkset_link_name(const opx_linkset *links, uint32_t link, const char **out_name) {
    return link_name(__func__, links, link, out_name);
}

}  // extern "C"
