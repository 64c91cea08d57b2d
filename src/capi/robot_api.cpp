// C shims: link sets from URDF, joints and forward kinematics.
#include "capi/checks.hpp"
#include "capi/handles.hpp"

#include <octoprox/robot.h>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

opx_status not_yet(const char *function) {
    return fail(OPX_ERROR_UNSUPPORTED, function, "not implemented yet");
}

}  // namespace

extern "C" {

OPX_API opx_status opx_urdf_options_init(opx_urdf_options *options, size_t size) {
    return init_struct(__func__, options, size, opx_urdf_options(OPX_URDF_OPTIONS_INIT), "options");
}

OPX_API opx_status opx_joint_info_init(opx_joint_info *info, size_t size) {
    return init_struct(__func__, info, size, opx_joint_info(OPX_JOINT_INFO_INIT), "info");
}

OPX_API opx_status opx_linkset_load_urdf_file(const char *, const opx_urdf_options *, opx_linkset **out) {
    if (out != nullptr) *out = nullptr;
    return not_yet(__func__);
}
OPX_API opx_status opx_linkset_load_urdf_string(const char *, const opx_urdf_options *, opx_linkset **out) {
    if (out != nullptr) *out = nullptr;
    return not_yet(__func__);
}
OPX_API opx_status opx_linkset_joint_count(const opx_linkset *, uint32_t *) { return not_yet(__func__); }
OPX_API opx_status opx_linkset_find_joint(const opx_linkset *, const char *, uint32_t *) { return not_yet(__func__); }
OPX_API opx_status opx_linkset_joint_info(const opx_linkset *, uint32_t, opx_joint_info *) { return not_yet(__func__); }
OPX_API opx_status opx_linkset_set_joint_positions(opx_linkset *, const double *, size_t, const opx_pose *) {
    return not_yet(__func__);
}
OPX_API opx_status opx_linkset_set_named_joint_positions(opx_linkset *, const char *const *, const double *,
                                                         size_t, const opx_pose *) {
    return not_yet(__func__);
}
OPX_API opx_status opx_linkset_get_joint_positions(const opx_linkset *, double *, size_t, size_t *) {
    return not_yet(__func__);
}
OPX_API opx_status opx_linkset_disabled_pair_count(const opx_linkset *, uint32_t *) { return not_yet(__func__); }
OPX_API opx_status opx_linkset_disabled_pair(const opx_linkset *, uint32_t, uint32_t *, uint32_t *) {
    return not_yet(__func__);
}

}  // extern "C"
