// C shims: the active joints of a link set made from URDF (robot.h), the
// joints whose values decide every link pose.
#include "capi/robot_inputs.hpp"

#include <octoprox/robot.h>

#include <algorithm>

using namespace octoprox;
using namespace octoprox::capi;

extern "C" {

OPX_API opx_status opx_linkset_get_active_joint_count(const opx_linkset *links, uint32_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        *out_count = static_cast<uint32_t>(links->robot.joints.active_joints().size());
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_active_joints(const opx_linkset *links, uint32_t *out_joint_indices,
                                                 size_t capacity, size_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        copy_list_out(links->robot.joints.active_joints(), out_joint_indices, capacity, out_count,
                      "out_joint_indices", "active joint count");
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_set_active_joint_positions(opx_linkset *links, const double *positions, size_t count,
                                                          const opx_pose *base_pose) {
    return guard(__func__, [&] {
        JointTree &joints = require_joints(links);
        const size_t active = joints.active_joints().size();
        if (count != active)
            throw_invalid(format("count %zu differs from the number of active joints, %zu (of %zu joints; "
                                 "opx_linkset_set_joint_positions takes all of them)",
                                 count, active, joints.joint_count()));
        require_joint_values(positions, count);
        const Pose base = read_base_pose(base_pose);
        joints.set_active_commanded(positions);
        apply_joint_positions(links, base);
        return OPX_OK;
    });
}

}  // extern "C"
