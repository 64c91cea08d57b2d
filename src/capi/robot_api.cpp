// C shims: link sets from URDF, joints and forward kinematics.
#include "base/file_bytes.hpp"
#include "capi/robot_inputs.hpp"
#include "robot/urdf_model.hpp"

#include <octoprox/robot.h>

#include <memory>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

// The caller's options, checked, with the default base directory.
UrdfInput read_options(const opx_urdf_options *in, const std::string &default_base_dir) {
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    read_versioned(in, options, "options");
    UrdfInput input;
    if (options.package_dir_count > 0) require_pointer(options.package_dirs, "options->package_dirs");
    for (size_t i = 0; i < options.package_dir_count; ++i) {
        if (options.package_dirs[i] == nullptr) throw_invalid(format("options->package_dirs[%zu] is NULL", i));
        input.paths.package_dirs.emplace_back(options.package_dirs[i]);
    }
    input.paths.base_dir = options.base_dir != nullptr ? options.base_dir : default_base_dir;
    if (options.srdf_path != nullptr) {
        if (options.srdf_path[0] == '\0') throw_invalid("options->srdf_path is empty (NULL means no SRDF)");
        input.srdf_path = options.srdf_path;
    }
    return input;
}

std::string read_text_file(const char *path) { return read_file_bytes(path, "path"); }

opx_status load(UrdfInput input, opx_linkset **out) {
    auto handle = std::make_unique<opx_linkset>();
    load_urdf(input, handle->links, handle->robot);
    *out = handle.release();
    return OPX_OK;
}

uint32_t require_joint(const opx_linkset *links, uint32_t joint) {
    if (joint >= links->robot.joints.joint_count())
        throw_invalid(format("joint %u does not exist (the set has %zu joints)", joint,
                             links->robot.joints.joint_count()));
    return joint;
}

opx_joint_info joint_info(const Joint &joint) {
    opx_joint_info info = OPX_JOINT_INFO_INIT;
    info.type = static_cast<int32_t>(joint.type);
    info.name = joint.name.c_str();
    info.parent_link = joint.parent_link, info.child_link = joint.child_link;
    for (int i = 0; i < 3; ++i) info.axis[i] = joint.axis[i];
    info.origin = pose_to_abi(joint.origin);
    info.has_limits = joint.has_limits ? 1 : 0;
    info.mimic_joint = joint.mimic;
    info.lower = joint.lower, info.upper = joint.upper;
    info.velocity = joint.velocity, info.effort = joint.effort;
    info.mimic_multiplier = joint.multiplier, info.mimic_offset = joint.offset;
    return info;
}

// The accessors, shared by their opx_linkset_get_* names and the aliases
// (each error names the function the caller called).
opx_status joint_count(const char *function, const opx_linkset *links, uint32_t *out_count) {
    return guard(function, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(links->robot.joints.joint_count());
        return OPX_OK;
    });
}

opx_status read_joint_info(const char *function, const opx_linkset *links, uint32_t joint, opx_joint_info *out) {
    return guard(function, [&] {
        require_pointer(links, "links");
        require_pointer(out, "out");
        write_versioned(out, joint_info(links->robot.joints.joint(require_joint(links, joint))), "out");
        return OPX_OK;
    });
}

opx_status disabled_pair_count(const char *function, const opx_linkset *links, uint32_t *out_count) {
    return guard(function, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(links->robot.disabled_pairs.size());
        return OPX_OK;
    });
}

opx_status disabled_pair(const char *function, const opx_linkset *links, uint32_t pair, uint32_t *out_link1,
                         uint32_t *out_link2) {
    return guard(function, [&] {
        require_pointer(links, "links");
        require_pointer(out_link1, "out_link1");
        require_pointer(out_link2, "out_link2");
        const auto &pairs = links->robot.disabled_pairs;
        if (pair >= pairs.size())
            throw_invalid(format("pair %u does not exist (the set has %zu disabled pairs)", pair, pairs.size()));
        *out_link1 = pairs[pair][0], *out_link2 = pairs[pair][1];
        return OPX_OK;
    });
}

}  // namespace

extern "C" {

OPX_API opx_status opx_urdf_options_init(opx_urdf_options *options, size_t size) {
    return init_struct(__func__, options, size, opx_urdf_options(OPX_URDF_OPTIONS_INIT), "options");
}

OPX_API opx_status opx_joint_info_init(opx_joint_info *info, size_t size) {
    return init_struct(__func__, info, size, opx_joint_info(OPX_JOINT_INFO_INIT), "info");
}

OPX_API opx_status opx_linkset_load_urdf_file(const char *path, const opx_urdf_options *options, opx_linkset **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(path, "path");
        require_pointer(out, "out");
        UrdfInput input = read_options(options, parent_dir(path));
        input.xml = read_text_file(path);
        input.source = format("path '%.200s'", path);
        return load(std::move(input), out);
    });
}

OPX_API opx_status opx_linkset_load_urdf_string(const char *xml, const opx_urdf_options *options, opx_linkset **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(xml, "xml");
        require_pointer(out, "out");
        UrdfInput input = read_options(options, "");
        input.xml = xml;
        input.source = "xml";
        return load(std::move(input), out);
    });
}

OPX_API opx_status opx_linkset_get_joint_count(const opx_linkset *links, uint32_t *out_count) {
    return joint_count(__func__, links, out_count);
}

OPX_API opx_status opx_linkset_find_joint(const opx_linkset *links, const char *name, uint32_t *out_joint) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(name, "name");
        require_pointer(out_joint, "out_joint");
        const uint32_t joint = links->robot.joints.find(name);
        if (joint == kNoIndex) throw_invalid(format("name \"%.80s\": no joint has this name", name));
        *out_joint = joint;
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_joint_info(const opx_linkset *links, uint32_t joint, opx_joint_info *out) {
    return read_joint_info(__func__, links, joint, out);
}

OPX_API opx_status opx_linkset_set_joint_positions(opx_linkset *links, const double *positions, size_t count,
                                                   const opx_pose *base_pose) {
    return guard(__func__, [&] {
        JointTree &joints = require_joints(links);
        if (count != joints.joint_count())
            throw_invalid(format("count %zu differs from the number of joints, %zu", count, joints.joint_count()));
        require_joint_values(positions, count);
        const Pose base = read_base_pose(base_pose);
        joints.set_commanded(positions);
        apply_joint_positions(links, base);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_set_named_joint_positions(opx_linkset *links, const char *const *names,
                                                         const double *positions, size_t count,
                                                         const opx_pose *base_pose) {
    return guard(__func__, [&] {
        JointTree &joints = require_joints(links);
        if (count > 0) require_pointer(names, "names"), require_pointer(positions, "positions");
        for (size_t i = 0; i < count; ++i) {
            if (names[i] == nullptr) throw_invalid(format("names[%zu] is NULL", i));
            if (joints.find(names[i]) == kNoIndex)
                throw_invalid(format("names[%zu] \"%.80s\": no joint has this name", i, names[i]));
            if (!joint_position_in_range(positions[i]))
                reject_joint_position(positions[i], format("positions[%zu] (joint \"%.80s\")", i, names[i]).c_str());
        }
        const Pose base = read_base_pose(base_pose);
        for (size_t i = 0; i < count; ++i) joints.set_commanded(joints.find(names[i]), positions[i]);
        apply_joint_positions(links, base);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_joint_positions(const opx_linkset *links, double *out, size_t capacity,
                                                   size_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        copy_list_out(links->robot.joints.positions(), out, capacity, out_count, "out", "joint count");
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_disabled_pair_count(const opx_linkset *links, uint32_t *out_count) {
    return disabled_pair_count(__func__, links, out_count);
}

OPX_API opx_status opx_linkset_get_disabled_pair(const opx_linkset *links, uint32_t pair, uint32_t *out_link1,
                                                 uint32_t *out_link2) {
    return disabled_pair(__func__, links, pair, out_link1, out_link2);
}

// Aliases of the opx_linkset_get_* accessors, kept for compatibility.
OPX_API opx_status opx_linkset_joint_count(const opx_linkset *links, uint32_t *out_count) {
    return joint_count(__func__, links, out_count);
}

OPX_API opx_status opx_linkset_joint_info(const opx_linkset *links, uint32_t joint, opx_joint_info *out) {
    return read_joint_info(__func__, links, joint, out);
}

OPX_API opx_status opx_linkset_disabled_pair_count(const opx_linkset *links, uint32_t *out_count) {
    return disabled_pair_count(__func__, links, out_count);
}

OPX_API opx_status opx_linkset_disabled_pair(const opx_linkset *links, uint32_t pair, uint32_t *out_link1,
                                             uint32_t *out_link2) {
    return disabled_pair(__func__, links, pair, out_link1, out_link2);
}

}  // extern "C"
