// C shim: every link pose of a link set at once (linkset.h).
#include "capi/robot_inputs.hpp"

#include <octoprox/linkset.h>

using namespace octoprox;
using namespace octoprox::capi;

extern "C" {

OPX_API opx_status opx_linkset_get_poses(const opx_linkset *links, opx_pose *out_poses, size_t capacity,
                                         size_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_count, "out_count");
        const size_t count = links->links.link_count();
        *out_count = count;
        if (capacity < count)
            throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                           format("capacity %zu is smaller than the link count %zu", capacity, count));
        if (count > 0) require_pointer(out_poses, "out_poses");
        for (size_t i = 0; i < count; ++i)
            out_poses[i] = pose_to_abi(links->links.link(static_cast<uint32_t>(i)).pose);
        return OPX_OK;
    });
}

}  // extern "C"
