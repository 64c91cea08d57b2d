// C shims: path queries.
#include "capi/checks.hpp"
#include "capi/world_handle.hpp"
#include "capi/handles.hpp"

using namespace octoprox;
using namespace octoprox::capi;

namespace {

PathSettings path_settings(const opx_path_request &merged, const SensorOctree *tree) {
    PathSettings settings;
    settings.collision = settings_for_map(collision_request_of(merged), tree);
    settings.distance = merged.compute_distance != 0;
    settings.distance_settings.threshold_log_odds = settings.collision.threshold_log_odds;
    settings.distance_settings.unknown_occupied = settings.collision.unknown_occupied;
    settings.distance_settings.point_extents = settings.collision.point_extents;
    return settings;
}

opx_path_result path_result_to_abi(const PathOutcome &o, const QueryContext &context) {
    opx_path_result result = OPX_PATH_RESULT_INIT;
    result.collided = o.first_collision >= 0 ? 1 : 0;
    result.first_colliding_waypoint = o.first_collision;
    result.min_distance = o.min_distance;
    result.min_distance_waypoint = o.min_distance_waypoint;
    result.total_cost = o.cost.total;
    result.cost_boxes_found = o.cost.box_count;
    result.cost_box_count = context.cost_boxes().size();
    result.narrow_tests = o.narrow_tests;
    return result;
}

// Reads every waypoint's poses up front, so a bad pose fails the call
// before any work.
std::vector<Pose> read_path_poses(const opx_pose *poses, size_t waypoints, size_t links, size_t pose_stride,
                                  size_t waypoint_stride) {
    const size_t step = pose_stride == 0 ? sizeof(opx_pose) : pose_stride;
    if (step < sizeof(opx_pose))
        throw_invalid(format("pose_stride %zu is smaller than one opx_pose (%zu bytes)", pose_stride, sizeof(opx_pose)));
    const size_t row = waypoint_stride == 0 ? links * step : waypoint_stride;
    if (links > 0 && row < (links - 1) * step + sizeof(opx_pose))
        throw_invalid(format("waypoint_stride %zu is smaller than one waypoint (%zu links)", waypoint_stride, links));
    if (waypoints > 0 && links > 0) require_pointer(poses, "poses");
    std::vector<Pose> all(waypoints * links);
    const auto *bytes = reinterpret_cast<const unsigned char *>(poses);
    for (size_t w = 0; w < waypoints; ++w) {
        for (size_t l = 0; l < links; ++l) {
            opx_pose pose;
            std::memcpy(&pose, bytes + w * row + l * step, sizeof pose);
            all[w * links + l] =
                read_pose_lazily(pose, [w, l] { return format("poses[waypoint %zu, link %zu]", w, l); });
        }
    }
    return all;
}

}  // namespace

extern "C" {

OPX_API opx_status opx_path_request_init(opx_path_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_path_request(OPX_PATH_REQUEST_INIT), "request");
}

OPX_API opx_status opx_path_result_init(opx_path_result *result, size_t size) {
    return init_struct(__func__, result, size, opx_path_result(OPX_PATH_RESULT_INIT), "result");
}

OPX_API opx_status opx_query_path(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                  const opx_pose *poses, size_t waypoint_count, size_t pose_stride,
                                  size_t waypoint_stride, const opx_path_request *request,
                                  opx_path_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        const SensorOctree *map = map_of(query, tree);
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_path_request merged = OPX_PATH_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const PathSettings settings = path_settings(merged, map);
        const std::vector<Pose> all =
            read_path_poses(poses, waypoint_count, links->links.link_count(), pose_stride, waypoint_stride);
        const PathOutcome o = query->context.path(map, links->links, all, waypoint_count, settings);
        write_versioned(out_result, path_result_to_abi(o, query->context), "out_result");
        return OPX_OK;
    });
}

}  // extern "C"
