// C shims: distance queries.
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/request_checks.hpp"
#include "capi/world_handle.hpp"
#include "narrowphase/narrow_phase.hpp"

using namespace octoprox;
using namespace octoprox::capi;

namespace {

DistanceSettings read_distance_request(const opx_distance_request &r, const SensorOctree &tree) {
    DistanceSettings s = read_distance_bounds(r);
    s.unknown_occupied = read_unknown_policy(r.unknown_policy, "request->unknown_policy");
    s.threshold_log_odds = read_threshold_log_odds(r.occupancy_threshold, tree, "request->occupancy_threshold");
    s.point_extents = read_obstacle_geometry(r.obstacle_geometry, "request->obstacle_geometry");
    return s;
}

}  // namespace

namespace octoprox::capi {

opx_distance_result distance_result_to_abi(const DistanceAnswer &answer, double cutoff) {
    const DistanceOutcome &o = answer.outcome;
    opx_distance_result out = OPX_DISTANCE_RESULT_INIT;
    out.found = o.found ? 1 : 0;
    out.narrow_tests = o.narrow_tests;
    out.distance = o.found ? o.distance : cutoff;
    if (!o.found) return out;
    // The same touch rule as collision queries, so the two agree.
    out.collided = o.distance <= kTouchTolerance ? 1 : 0;
    out.cell_class = answer.cell.cell_class;
    out.link = o.link, out.shape = o.shape, out.attached = o.attached;
    for (int axis = 0; axis < 3; ++axis) {
        out.point_on_link[axis] = o.on_link[axis];
        out.point_on_cell[axis] = o.on_cell[axis];
        out.cell_center[axis] = answer.cell.center[axis];
    }
    out.cell_size = answer.cell.size;
    out.cell_probability = answer.cell.probability;
    out.object = answer.object;
    out.object_shape = answer.object_shape;
    return out;
}

}  // namespace octoprox::capi

extern "C" {

OPX_API opx_status opx_distance_request_init(opx_distance_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_distance_request(OPX_DISTANCE_REQUEST_INIT), "request");
}

OPX_API opx_status opx_distance_result_init(opx_distance_result *result, size_t size) {
    return init_struct(__func__, result, size, opx_distance_result(OPX_DISTANCE_RESULT_INIT), "result");
}

OPX_API opx_status opx_query_distance(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                      const opx_distance_request *request, opx_distance_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        const SensorOctree *map = map_of(query, tree);
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_distance_request merged = OPX_DISTANCE_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const DistanceSettings settings =
            map != nullptr ? read_distance_request(merged, *map) : distance_settings_without_map(merged);
        const bool per_link = merged.per_link != 0;
        const DistanceAnswer answer = query->context.distance(map, links->links, settings, per_link);
        write_versioned(out_result, distance_result_to_abi(answer, settings.cutoff), "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_get_link_distances(const opx_query *query, double *out_distances,
                                                size_t capacity, size_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(out_count, "out_count");
        if (capacity > 0) require_pointer(out_distances, "out_distances");
        const std::vector<double> &d = query->context.link_distances();
        *out_count = d.size();
        std::copy(d.begin(), d.begin() + std::min(capacity, d.size()), out_distances);
        if (d.size() > capacity)
            throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                           format("out_distances holds %zu values, %zu links need one each", capacity, d.size()));
        return OPX_OK;
    });
}

}  // extern "C"
