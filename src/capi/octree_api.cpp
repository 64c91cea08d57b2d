// C shims: octree lifetime, options, insertion.
#include "capi/checks.hpp"
#include "capi/handles.hpp"

namespace octoprox::capi {

OctreeParams params_from_options(const opx_octree_options &o) {
    OctreeParams p;
    p.resolution = o.resolution;
    p.prob_hit = o.prob_hit;
    p.prob_miss = o.prob_miss;
    p.clamp_min = o.clamp_min;
    p.clamp_max = o.clamp_max;
    p.occupied_threshold = o.occupied_threshold;
    p.free_threshold = o.free_threshold;
    return p;
}

opx_octree_options options_from_params(const OctreeParams &p) {
    return opx_octree_options{sizeof(opx_octree_options), 0, p.resolution, p.prob_hit, p.prob_miss,
                              p.clamp_min, p.clamp_max, p.occupied_threshold, p.free_threshold};
}

OctreeParams read_octree_options(const opx_octree_options *options, const char *argument) {
    opx_octree_options merged = OPX_OCTREE_OPTIONS_INIT;
    read_versioned(options, merged, argument);
    OctreeParams params = params_from_options(merged);
    validate_params(params, argument);
    return params;
}

namespace {

PointSource read_point_source(const void *points, size_t count, size_t stride, int32_t scalar_type) {
    if (scalar_type != OPX_SCALAR_FLOAT32 && scalar_type != OPX_SCALAR_FLOAT64)
        throw_invalid(format("scalar_type %d is neither OPX_SCALAR_FLOAT32 (1) nor "
                             "OPX_SCALAR_FLOAT64 (2)",
                             scalar_type));
    PointSource source;
    source.is_double = scalar_type == OPX_SCALAR_FLOAT64;
    const size_t point_bytes = 3 * (source.is_double ? sizeof(double) : sizeof(float));
    if (stride != 0 && stride < point_bytes)
        throw_invalid(format("stride %zu is smaller than one point (3 %s = %zu bytes)", stride,
                             source.is_double ? "doubles" : "floats", point_bytes));
    if (count > 0) require_pointer(points, "points");
    const size_t step = stride == 0 ? point_bytes : stride;
    if (count > 0 && count - 1 > (SIZE_MAX - point_bytes) / step)
        throw_invalid(format("count %zu with stride %zu spans more bytes than memory has", count, step));
    source.data = static_cast<const unsigned char *>(points);
    source.count = count;
    source.stride = stride == 0 ? point_bytes : stride;
    return source;
}

}  // namespace

namespace {

// The self-filtering fields: a robot at a known pose, a padding that is a
// distance, and clearing only with a robot.
void read_robot_fields(const opx_insert_options &merged, InsertRequest &request) {
    if (merged.robot != nullptr) {
        request.robot = &merged.robot->links;
        if (!request.robot->poses_set())
            throw_invalid("options.robot has no poses: set them (opx_linkset_set_poses, or a robot's "
                          "joint positions) to the robot's state when the frame was captured");
    }
    if (!(std::isfinite(merged.robot_padding) && merged.robot_padding >= 0.0))
        throw_invalid(format("options.robot_padding is %g; a padding is a finite distance >= 0 (metres)",
                             merged.robot_padding));
    if (merged.clear_robot_volume != 0 && merged.robot == nullptr)
        throw_invalid("options.clear_robot_volume is set but options.robot is NULL: there is no robot volume to clear");
    request.robot_padding = merged.robot_padding;
    request.clear_robot_volume = merged.clear_robot_volume != 0;
}

}  // namespace

InsertRequest read_insert_options(const opx_insert_options *options) {
    opx_insert_options merged = OPX_INSERT_OPTIONS_INIT;
    read_versioned(options, merged, "options");
    if (merged.mode != OPX_INSERT_RAYCAST && merged.mode != OPX_INSERT_ENDPOINTS)
        throw_invalid(format("options.mode %d is neither OPX_INSERT_RAYCAST (0) nor "
                             "OPX_INSERT_ENDPOINTS (1)",
                             merged.mode));
    if (std::isnan(merged.max_range)) throw_invalid("options.max_range is NaN");
    InsertRequest request;
    InsertSettings &settings = request.settings;
    settings.raycast = merged.mode == OPX_INSERT_RAYCAST;
    settings.sensor_pose = read_pose(merged.sensor_pose, "options.sensor_pose");
    settings.max_range = merged.max_range;
    settings.max_threads = merged.max_threads;
    read_robot_fields(merged, request);
    if (merged.use_bounds != 0) {
        read_box(merged.bounds_min, merged.bounds_max, 1.0, "options.bounds_min", "options.bounds_max");
        request.use_bounds = true;
        std::copy(merged.bounds_min, merged.bounds_min + 3, request.bounds_min);
        std::copy(merged.bounds_max, merged.bounds_max + 3, request.bounds_max);
    }
    return request;
}

opx_insert_report report_from_counts(const InsertCounts &c) {
    return opx_insert_report{sizeof(opx_insert_report), 0, c.used, c.nonfinite, c.out_of_range,
                             c.outside_map, c.cells_hit, c.cells_missed, 0, c.on_robot, c.shadowed,
                             c.cells_cleared};
}

}  // namespace octoprox::capi

using namespace octoprox;
using namespace octoprox::capi;

extern "C" {

OPX_API opx_status opx_octree_options_init(opx_octree_options *options, size_t size) {
    return init_struct(__func__, options, size, opx_octree_options(OPX_OCTREE_OPTIONS_INIT), "options");
}

OPX_API opx_status opx_insert_options_init(opx_insert_options *options, size_t size) {
    return init_struct(__func__, options, size, opx_insert_options(OPX_INSERT_OPTIONS_INIT), "options");
}

OPX_API opx_status opx_insert_report_init(opx_insert_report *report, size_t size) {
    return init_struct(__func__, report, size, opx_insert_report(OPX_INSERT_REPORT_INIT), "report");
}

OPX_API opx_status opx_octree_create(const opx_octree_options *options, opx_octree **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(out, "out");
        const OctreeParams params = read_octree_options(options, "options");
        auto handle = std::make_unique<opx_octree>();
        handle->tree = std::make_unique<SensorOctree>(params);
        *out = handle.release();
        return OPX_OK;
    });
}

OPX_API void opx_octree_destroy(opx_octree *tree) { delete tree; }

OPX_API opx_status opx_octree_clear(opx_octree *tree) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        tree->tree->clear();
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_get_options(const opx_octree *tree, opx_octree_options *out) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        write_versioned(out, options_from_params(tree->tree->params()), "out");
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_insert_points(opx_octree *tree, const void *points, size_t count,
                                            size_t stride, int32_t scalar_type,
                                            const opx_insert_options *options,
                                            opx_insert_report *out_report) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        if (out_report != nullptr) require_struct_size(out_report->struct_size, "out_report");
        const PointSource source = read_point_source(points, count, stride, scalar_type);
        const InsertRequest request = read_insert_options(options);
        const InsertCounts counts = run_insert(*tree->tree, source, request);
        if (out_report != nullptr) write_versioned(out_report, report_from_counts(counts), "out_report");
        return OPX_OK;
    });
}

}  // extern "C"
