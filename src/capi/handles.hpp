// The opaque handles of the C ABI and their C++ contents.
#pragma once

#include "octree/sensor_octree.hpp"
#include "query/batch/batch_worker.hpp"
#include "query/context.hpp"
#include "robot/linkset.hpp"
#include "robot/robot_model.hpp"

#include <octoprox/octree.h>
#include <octoprox/query.h>

#include <memory>

struct opx_octree {
    std::unique_ptr<octoprox::SensorOctree> tree;
};

struct opx_linkset {
    octoprox::LinkSet links;
    octoprox::RobotModel robot;  // joints: empty unless made from URDF
    std::vector<octoprox::Pose> pose_scratch;  // opx_linkset_set_poses: no allocation per call
};

struct opx_query {
    explicit opx_query(const octoprox::ContextOptions &options) : context(options), batch(options) {}
    octoprox::QueryContext context;
    octoprox::BatchWorkers batch;  // the batch queries' workers (batch.h), kept between calls
};

namespace octoprox::capi {

// Conversions between the ABI's option struct and the internal parameters.
OctreeParams params_from_options(const opx_octree_options &options);
opx_octree_options options_from_params(const OctreeParams &params);
// Caller's options (NULL: defaults) read, versioned and validated.
OctreeParams read_octree_options(const opx_octree_options *options, const char *argument);
// An insert's settings and its robot (self-filtering), read from the
// caller's options.
struct InsertRequest {
    InsertSettings settings;
    const LinkSet *robot = nullptr;  // nullptr: no self-filtering
    double robot_padding = 0.0;
    bool clear_robot_volume = false;
    // options.use_bounds: the box, checked (map frame, metres).
    bool use_bounds = false;
    double bounds_min[3] = {0, 0, 0}, bounds_max[3] = {0, 0, 0};
};
// The cells of a caller's box [box_min, box_max] (NaN or inverted: an
// invalid argument naming min_name or max_name).
CellRange read_box(const double box_min[3], const double box_max[3], double resolution, const char *min_name,
                  const char *max_name);
// Caller's insert options (NULL: defaults) read, versioned and validated.
InsertRequest read_insert_options(const opx_insert_options *options);
// Inserts the points with the request's robot filtered out (insert_robot.cpp).
InsertCounts run_insert(SensorOctree &tree, const PointSource &points, const InsertRequest &request);
// The public form of an insert's counts (pixels_no_return 0).
opx_insert_report report_from_counts(const InsertCounts &counts);
// A collision request (already versioned) checked and turned into settings.
CollisionSettings collision_settings(const opx_collision_request &request, const SensorOctree &tree);
// The fields a path or motion request shares with a collision request, the
// others at the collision request's defaults.
template <class Request>
opx_collision_request collision_request_of(const Request &r) {
    opx_collision_request c = OPX_COLLISION_REQUEST_INIT;
    c.unknown_policy = r.unknown_policy;
    c.occupancy_threshold = r.occupancy_threshold;
    c.compute_cost = r.compute_cost;
    c.max_cost_boxes = r.max_cost_boxes;
    c.unknown_probability = r.unknown_probability;
    c.obstacle_geometry = r.obstacle_geometry;
    for (int axis = 0; axis < 3; ++axis) {
        c.region_min[axis] = r.region_min[axis];
        c.region_max[axis] = r.region_max[axis];
    }
    return c;
}
// The public form of a cost box.
opx_cost_box cost_box_to_abi(const CostBox &box, double resolution);
// The public form of a collision answer, its contacts and cost boxes
// being the context's.
opx_collision_result collision_result_to_abi(const CollisionAnswer &answer, const QueryContext &context);
// The public form of a distance answer (not found: the distance is the cutoff).
opx_distance_result distance_result_to_abi(const DistanceAnswer &answer, double cutoff);

}  // namespace octoprox::capi
