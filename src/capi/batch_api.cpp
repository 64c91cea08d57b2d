// C shims: many configurations and joint-space motions per call (batch.h).
#include "capi/batch_inputs.hpp"
#include "capi/checks.hpp"
#include "capi/request_checks.hpp"
#include "capi/world_handle.hpp"
#include "query/batch/configuration_batch.hpp"
#include "query/batch/motion_check.hpp"

#include <cmath>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

// The octree the call reads: null when tree is NULL and the query has a
// world (its objects alone).
Obstacles require_handles(const opx_query *query, const opx_octree *tree, const opx_linkset *links) {
    require_pointer(query, "query");
    const SensorOctree *map = map_of(query, tree);
    require_pointer(links, "links");
    return Obstacles{map, query->context.world()};
}

ConfigurationSettings configuration_settings(const opx_batch_request &r, const SensorOctree *tree) {
    ConfigurationSettings s;
    s.collision = yes_no_settings(r.unknown_policy, r.occupancy_threshold, tree);
    s.collision.point_extents = read_obstacle_geometry(r.obstacle_geometry, "request->obstacle_geometry");
    s.self_collision = r.self_collision != 0;
    s.distance = r.compute_distance != 0;
    s.distance_settings.unknown_occupied = s.collision.unknown_occupied;
    s.distance_settings.threshold_log_odds = s.collision.threshold_log_odds;
    s.distance_settings.point_extents = s.collision.point_extents;
    if (std::isnan(r.distance_cutoff) || r.distance_cutoff < 0.0)
        throw_invalid(format("request->distance_cutoff is %g; 0 (none) or a positive distance is needed",
                             r.distance_cutoff));
    if (r.distance_cutoff > 0.0) s.distance_settings.cutoff = r.distance_cutoff;
    s.threads = r.max_threads;
    return s;
}

// The motion request's fields shared with a collision request; a motion
// check keeps no contacts.
opx_collision_request as_collision_request(const opx_motion_request &r) {
    opx_collision_request c = collision_request_of(r);
    c.max_contacts = 0;
    return c;
}

// The distances a certified check advances by: to the obstacles the
// collision settings name.
CertifiedSettings certified_settings(const opx_motion_request &r, const CollisionSettings &collision) {
    if (!(r.tolerance > 0.0 && r.tolerance <= 1.0))
        throw_invalid(format("request->tolerance is %g; a fraction of the motion in (0, 1] is needed", r.tolerance));
    if (r.compute_cost != 0)
        throw_invalid("request->compute_cost is 1; the swept cost is given by OPX_MOTION_SAMPLED checks only");
    CertifiedSettings s;
    s.distance.threshold_log_odds = collision.threshold_log_odds;
    s.distance.unknown_occupied = collision.unknown_occupied;
    s.distance.point_extents = collision.point_extents;
    s.self_collision = r.self_collision != 0;
    s.tolerance = r.tolerance;
    return s;
}

MotionSettings motion_settings(const opx_motion_request &r, const SensorOctree *tree) {
    MotionSettings s;
    s.collision = settings_for_map(as_collision_request(r), tree);
    s.self_collision = r.self_collision != 0;
    s.threads = r.max_threads;
    if (r.check != OPX_MOTION_SAMPLED && r.check != OPX_MOTION_CERTIFIED)
        throw_invalid(format("request->check is %d; OPX_MOTION_SAMPLED (0) or OPX_MOTION_CERTIFIED (1) is needed",
                             r.check));
    s.certified = r.check == OPX_MOTION_CERTIFIED;
    if (s.certified) {
        s.certified_settings = certified_settings(r, s.collision);
        return s;
    }
    if (!(r.resolution > 0.0) || !std::isfinite(r.resolution))
        throw_invalid(format("request->resolution is %g; a finite step > 0 (rad or m) is needed", r.resolution));
    s.resolution = r.resolution;
    return s;
}

opx_motion_result motion_result_to_abi(const MotionAnswer &a, bool cost, const QueryContext &context) {
    opx_motion_result out = OPX_MOTION_RESULT_INIT;
    out.collided = a.collided() ? 1 : 0;
    out.first_collision_fraction = a.fraction();
    out.steps = a.steps;
    out.configurations_checked = a.samples_checked;
    if (cost) {
        out.total_cost = a.path.cost.total;
        out.cost_boxes_found = a.path.cost.box_count;
        out.cost_box_count = context.cost_boxes().size();
    }
    return out;
}

MotionAnswer run_motion(opx_query *query, const Obstacles &obstacles, const opx_linkset *links,
                        const JointTree &joints, const double *start, const double *goal, const Pose &base,
                        const MotionSettings &settings) {
    query->batch.prepare(1, links->links, joints, obstacles.world);
    BatchWorker &worker = query->batch[0];
    MotionScratch scratch;
    if (settings.certified)
        return MotionAnswer::of(check_certified(worker, scratch.certified, obstacles.tree, joints, start, goal, base,
                                                settings.certified_settings));
    double largest = 0.0;
    const double steps = motion_steps(worker.robot(), scratch, start, goal, settings.resolution, largest);
    require_motion_steps(steps, largest, settings.resolution, "the motion from start to goal");
    const auto n = static_cast<uint64_t>(steps);
    if (settings.collision.cost)
        return check_motion_with_cost(worker, query->context, *obstacles.tree, links->links, start, goal, n, base,
                                      settings);
    return check_motion(worker, scratch, obstacles.tree, start, goal, n, base, settings);
}

}  // namespace

extern "C" {

OPX_API opx_status opx_batch_request_init(opx_batch_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_batch_request(OPX_BATCH_REQUEST_INIT), "request");
}

OPX_API opx_status opx_motion_request_init(opx_motion_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_motion_request(OPX_MOTION_REQUEST_INIT), "request");
}

OPX_API opx_status opx_motion_result_init(opx_motion_result *result, size_t size) {
    return init_struct(__func__, result, size, opx_motion_result(OPX_MOTION_RESULT_INIT), "result");
}

OPX_API opx_status opx_query_check_configurations(opx_query *query, const opx_octree *tree,
                                                  const opx_linkset *links, const double *positions,
                                                  size_t configuration_count, size_t joint_count, size_t stride,
                                                  const opx_pose *base_poses, size_t base_pose_count,
                                                  size_t base_pose_stride, const opx_batch_request *request,
                                                  uint8_t *out_collided, double *out_distances, size_t capacity) {
    return guard(__func__, [&] {
        const Obstacles obstacles = require_handles(query, tree, links);
        opx_batch_request merged = OPX_BATCH_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const JointLayout layout = read_joint_layout(links, joint_count, merged.joint_order);
        const ConfigurationSettings settings = configuration_settings(merged, obstacles.tree);
        require_rows(configuration_count, "configuration_count", capacity);
        require_pointer(out_collided, "out_collided");
        if (settings.distance) require_pointer(out_distances, "out_distances");
        const JointRows rows = read_joint_rows(positions, configuration_count, layout, stride, "positions");
        const BasePoses bases = read_base_poses(base_poses, base_pose_count, base_pose_stride, configuration_count);
        check_configurations(query->batch, obstacles, links->links, *layout.joints, rows, bases, settings,
                             ConfigurationOutputs{out_collided, out_distances});
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_check_motion(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                          const double *start, const double *goal, size_t joint_count,
                                          const opx_pose *base_pose, const opx_motion_request *request,
                                          opx_motion_result *out_result) {
    return guard(__func__, [&] {
        const Obstacles obstacles = require_handles(query, tree, links);
        require_out_struct(out_result, "out_result");
        opx_motion_request merged = OPX_MOTION_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const JointLayout layout = read_joint_layout(links, joint_count, merged.joint_order);
        const MotionSettings settings = motion_settings(merged, obstacles.tree);
        const JointRows starts = read_joint_rows(start, 1, layout, 0, "start");
        const JointRows goals = read_joint_rows(goal, 1, layout, 0, "goal");
        const BasePoses base = read_base_poses(base_pose, base_pose == nullptr ? 0 : 1, 0, 1);
        std::vector<double> from(starts.model_count()), to(goals.model_count());
        starts.read(0, from.data()), goals.read(0, to.data());
        const MotionAnswer answer =
            run_motion(query, obstacles, links, *layout.joints, from.data(), to.data(), base.at(0), settings);
        write_versioned(out_result, motion_result_to_abi(answer, settings.collision.cost, query->context),
                        "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_check_motions(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                           const double *starts, const double *goals, size_t motion_count,
                                           size_t joint_count, size_t stride, const opx_pose *base_poses,
                                           size_t base_pose_count, size_t base_pose_stride,
                                           const opx_motion_request *request, uint8_t *out_collided,
                                           double *out_first_fractions, size_t capacity) {
    return guard(__func__, [&] {
        const Obstacles obstacles = require_handles(query, tree, links);
        opx_motion_request merged = OPX_MOTION_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const JointLayout layout = read_joint_layout(links, joint_count, merged.joint_order);
        const MotionSettings settings = motion_settings(merged, obstacles.tree);
        if (settings.collision.cost)
            throw_invalid("request->compute_cost is 1; the swept cost is given by opx_query_check_motion only");
        require_rows(motion_count, "motion_count", capacity);
        require_pointer(out_collided, "out_collided");
        const JointRows from = read_joint_rows(starts, motion_count, layout, stride, "starts");
        const JointRows to = read_joint_rows(goals, motion_count, layout, stride, "goals");
        const BasePoses bases = read_base_poses(base_poses, base_pose_count, base_pose_stride, motion_count);
        check_motions(query->batch, obstacles, links->links, *layout.joints, from, to, bases, settings, out_collided,
                      out_first_fractions);
        return OPX_OK;
    });
}

}  // extern "C"
