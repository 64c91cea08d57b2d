// C shims: a caller's boxes as the map of an amortized context (a
// "collision map" from another source, paper IV.A).
#include "capi/checks.hpp"
#include "capi/world_handle.hpp"
#include "capi/handles.hpp"
#include "capi/request_checks.hpp"

#include <cmath>
#include <cstring>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

constexpr size_t kBoxBytes = 6 * sizeof(double);

std::vector<Aabb> read_boxes(const double *boxes, size_t count, size_t stride) {
    if (stride != 0 && stride < kBoxBytes)
        throw_invalid(format("stride %zu is smaller than one box (6 doubles, %zu bytes)", stride, kBoxBytes));
    if (count > 0) require_pointer(boxes, "boxes");
    const size_t step = stride == 0 ? kBoxBytes : stride;
    std::vector<Aabb> out(count);
    for (size_t i = 0; i < count; ++i) {
        double v[6];
        std::memcpy(v, reinterpret_cast<const unsigned char *>(boxes) + i * step, sizeof v);
        for (double x : v)
            if (!std::isfinite(x)) throw_invalid(format("boxes[%zu] holds a non-finite value", i));
        for (int axis = 0; axis < 3; ++axis)
            if (v[axis] > v[axis + 3])
                throw_invalid(format("boxes[%zu]: min %g > max %g on axis %d", i, v[axis], v[axis + 3], axis));
        out[i] = Aabb{Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5])};
    }
    return out;
}

// occupancy_threshold, unknown_policy and obstacle_geometry do not apply
// to boxes (checked for validity only, so one request serves octrees and
// boxes alike).
void check_shared_fields(int32_t unknown_policy, double threshold, int32_t obstacle_geometry) {
    read_unknown_policy(unknown_policy, "request->unknown_policy");
    read_obstacle_geometry(obstacle_geometry, "request->obstacle_geometry");
    if (!(threshold == 0.0 || (threshold > 0.0 && threshold < 1.0)))
        throw_invalid(format("request->occupancy_threshold is %g; 0 or a probability in (0, 1) is needed", threshold));
}

CollisionSettings box_collision_settings(const opx_collision_request &r) {
    check_shared_fields(r.unknown_policy, r.occupancy_threshold, r.obstacle_geometry);
    if (r.compute_cost) throw_invalid("request->compute_cost: caller boxes have no uncertain or unknown space");
    CollisionSettings s;
    s.max_contacts = r.max_contacts;
    s.penetration = r.compute_penetration != 0;
    return s;
}

DistanceSettings box_distance_settings(const opx_distance_request &r) {
    check_shared_fields(r.unknown_policy, r.occupancy_threshold, r.obstacle_geometry);
    return read_distance_bounds(r);
}

}  // namespace

extern "C" {

OPX_API opx_status opx_query_bind_boxes(opx_query *query, const double *boxes, size_t count, size_t stride) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        query->context.require_box_engine();
        query->context.bind_boxes(read_boxes(boxes, count, stride));
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_collide_boxes(opx_query *query, const opx_linkset *links,
                                           const opx_collision_request *request, opx_collision_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(links, "links");
        refuse_world(query);
        require_out_struct(out_result, "out_result");
        opx_collision_request merged = OPX_COLLISION_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const CollisionSettings settings = box_collision_settings(merged);
        const CollisionAnswer answer = query->context.collide_boxes(links->links, settings);
        write_versioned(out_result, collision_result_to_abi(answer, query->context), "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_distance_boxes(opx_query *query, const opx_linkset *links,
                                            const opx_distance_request *request, opx_distance_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(links, "links");
        refuse_world(query);
        require_out_struct(out_result, "out_result");
        opx_distance_request merged = OPX_DISTANCE_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const DistanceSettings settings = box_distance_settings(merged);
        const DistanceAnswer answer = query->context.distance_boxes(links->links, settings, merged.per_link != 0);
        write_versioned(out_result, distance_result_to_abi(answer, settings.cutoff), "out_result");
        return OPX_OK;
    });
}

}  // extern "C"
