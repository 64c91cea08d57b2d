// C shim: the obstacle cost of a trajectory of spheres and its gradient
// (spheres.h).
#include "capi/batch_inputs.hpp"
#include "capi/checks.hpp"
#include "capi/request_checks.hpp"
#include "capi/robot_inputs.hpp"
#include "capi/world_handle.hpp"
#include "query/spheres/trajectory_cost.hpp"

#include <octoprox/spheres.h>

#include <cmath>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

SphereDistanceSettings cost_settings(const opx_trajectory_cost_request &r, const SensorOctree *tree) {
    SphereDistanceSettings s;
    const CollisionSettings map = yes_no_settings(r.unknown_policy, r.occupancy_threshold, tree);
    s.map.unknown_occupied = map.unknown_occupied;
    s.map.threshold_log_odds = map.threshold_log_odds;
    s.map.point_extents = read_obstacle_geometry(r.obstacle_geometry, "request->obstacle_geometry");
    if (!(r.activation > 0.0 && std::isfinite(r.activation)))
        throw_invalid(format("request->activation is %g; a positive finite distance is needed", r.activation));
    s.max_distance = r.activation;
    return s;
}

// The waypoints' costs, summed in order, and their gradients in the
// rows' order.
double trajectory_cost(const TrajectorySpheres &robot, const SensorOctree *tree, const ObstacleGrid *grid,
                       const World *world, const JointTree &joints, const JointRows &rows, const Pose &base,
                       const SphereDistanceSettings &settings, double *out_gradient) {
    const WorldIndex *index = nullptr;
    if (world != nullptr) {
        index = &world->index();
        for (const PlacedShape *shape : index->shapes)
            if (shape->kind == ShapeKind::kMesh) shape->place_mesh();
    }
    TrajectorySpheres::Scratch scratch;
    std::vector<double> commanded(rows.model_count()), gradient(joints.joint_count());
    double cost = 0.0;
    for (size_t w = 0; w < rows.count; ++w) {
        rows.read(w, commanded.data());
        std::fill(gradient.begin(), gradient.end(), 0.0);
        cost += robot.waypoint(tree, grid, index, joints, commanded.data(), base, settings, gradient.data(), scratch);
        if (out_gradient == nullptr) continue;
        double *row = out_gradient + w * rows.joint_count;
        for (size_t i = 0; i < rows.joint_count; ++i) row[i] = rows.active != nullptr ? gradient[(*rows.active)[i]] : gradient[i];
    }
    return cost;
}

}  // namespace

extern "C" {

OPX_API opx_status opx_trajectory_cost_request_init(opx_trajectory_cost_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_trajectory_cost_request(OPX_TRAJECTORY_COST_REQUEST_INIT),
                       "request");
}

OPX_API opx_status opx_query_trajectory_cost(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                             const double *positions, size_t waypoint_count, size_t joint_count,
                                             size_t stride, const opx_pose *base_pose,
                                             const opx_trajectory_cost_request *request, double *out_cost,
                                             double *out_gradient, size_t capacity) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        const SensorOctree *map = map_of(query, tree);
        require_pointer(links, "links");
        opx_trajectory_cost_request merged = OPX_TRAJECTORY_COST_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const SphereDistanceSettings settings = cost_settings(merged, map);
        const JointLayout layout = read_joint_layout(links, joint_count, merged.joint_order);
        require_pointer(out_cost, "out_cost");
        if (waypoint_count == 0) throw_invalid("waypoint_count is 0; give at least one waypoint");
        if (out_gradient != nullptr && capacity < waypoint_count)
            throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                           format("capacity %zu is smaller than waypoint_count, %zu", capacity, waypoint_count));
        const JointRows rows = read_joint_rows(positions, waypoint_count, layout, stride, "positions");
        const Pose base = read_base_pose(base_pose);
        TrajectorySpheres robot;
        if (!robot.bind(links->links, *layout.joints))
            throw_invalid("links holds a shape that is not a sphere; the trajectory cost needs a robot of spheres");
        const ObstacleGrid *grid = map == nullptr || settings.map.unknown_occupied
                                       ? nullptr
                                       : query->context.obstacle_grid(*map, settings.map.threshold_log_odds);
        *out_cost = trajectory_cost(robot, map, grid, query->context.world(), *layout.joints, rows, base, settings,
                                    out_gradient);
        return OPX_OK;
    });
}

}  // extern "C"
