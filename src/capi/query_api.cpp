// C shims: query contexts and collision queries.
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/request_checks.hpp"
#include "capi/world_handle.hpp"

using namespace octoprox;
using namespace octoprox::capi;

namespace octoprox::capi {

CollisionSettings collision_settings(const opx_collision_request &merged, const SensorOctree &tree) {
    CollisionSettings settings;
    settings.unknown_occupied = read_unknown_policy(merged.unknown_policy, "request->unknown_policy");
    settings.threshold_log_odds =
        read_threshold_log_odds(merged.occupancy_threshold, tree, "request->occupancy_threshold");
    settings.max_contacts = merged.max_contacts;
    settings.cost = merged.compute_cost != 0;
    settings.penetration = merged.compute_penetration != 0;
    settings.point_extents = read_obstacle_geometry(merged.obstacle_geometry, "request->obstacle_geometry");
    if (settings.cost) {
        const double p = merged.unknown_probability;
        if (!(p >= 0.0 && p <= 1.0))
            throw_invalid(format("request->unknown_probability is %g; a probability in [0, 1] is needed", p));
        for (int axis = 0; axis < 3; ++axis)
            if (!std::isfinite(merged.region_min[axis]) || !std::isfinite(merged.region_max[axis]))
                throw_invalid("request->region_min/region_max hold a non-finite value");
        settings.unknown_probability = p;
        settings.max_cost_boxes = merged.max_cost_boxes;
        settings.free_log_odds = static_cast<float>(log_odds(tree.params().free_threshold));
        const Aabb region{Vec3(merged.region_min[0], merged.region_min[1], merged.region_min[2]),
                          Vec3(merged.region_max[0], merged.region_max[1], merged.region_max[2])};
        settings.region = region.has_volume() ? region : tree.known_bounds();
    }
    return settings;
}

opx_cost_box cost_box_to_abi(const CostBox &b, double resolution) {
    opx_cost_box out = OPX_COST_BOX_INIT;
    out.link = b.link;
    out.cell_class = b.cell_class;
    for (int axis = 0; axis < 3; ++axis) {
        out.min[axis] = b.box.lo[axis];
        out.max[axis] = b.box.hi[axis];
        out.cell_center[axis] = b.cell.center(axis, resolution);
    }
    out.probability = b.probability;
    out.cost = b.cost;
    out.cell_size = b.cell.size(resolution);
    return out;
}

opx_collision_result collision_result_to_abi(const CollisionAnswer &answer, const QueryContext &context) {
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    result.collided = answer.outcome.collided ? 1 : 0;
    result.contact_count = context.contacts().size() + context.world_contacts().size();
    result.truncated = answer.outcome.truncated ? 1 : 0;
    result.narrow_tests = answer.outcome.narrow_tests;
    result.total_cost = answer.cost.total;
    result.cost_boxes_found = answer.cost.box_count;
    result.cost_box_count = context.cost_boxes().size();
    return result;
}

}  // namespace octoprox::capi

namespace {

// The options checked and turned into the context's.
ContextOptions context_options(const opx_query_options &merged) {
    if (merged.engine != OPX_ENGINE_DIRECT && merged.engine != OPX_ENGINE_AMORTIZED)
        throw_invalid(format("options->engine %d is neither OPX_ENGINE_DIRECT (1) nor OPX_ENGINE_AMORTIZED (2)",
                             merged.engine));
    if (merged.morton_bits < 1 || merged.morton_bits > 21)
        throw_invalid(format("options->morton_bits %u is outside 1..21", merged.morton_bits));
    ContextOptions options;
    options.engine = merged.engine == OPX_ENGINE_AMORTIZED ? EngineKind::kAmortized : EngineKind::kDirect;
    options.amortized.refine_steps = merged.refine_steps;
    options.amortized.morton_bits = static_cast<int>(merged.morton_bits);
    return options;
}

int32_t engine_to_abi(EngineKind kind) {
    return kind == EngineKind::kAmortized ? OPX_ENGINE_AMORTIZED : OPX_ENGINE_DIRECT;
}

opx_contact contact_to_abi(const Contact &c) {
    return opx_contact{sizeof(opx_contact), c.link, c.shape, c.cell_class,
                       {c.center[0], c.center[1], c.center[2]}, c.size, c.probability, c.depth,
                       {c.normal[0], c.normal[1], c.normal[2]}, {c.position[0], c.position[1], c.position[2]},
                       -1, 0, c.attached, 0};
}

}  // namespace

extern "C" {

OPX_API opx_status opx_query_options_init(opx_query_options *options, size_t size) {
    return init_struct(__func__, options, size, opx_query_options(OPX_QUERY_OPTIONS_INIT), "options");
}

OPX_API opx_status opx_collision_request_init(opx_collision_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_collision_request(OPX_COLLISION_REQUEST_INIT), "request");
}

OPX_API opx_status opx_collision_result_init(opx_collision_result *result, size_t size) {
    return init_struct(__func__, result, size, opx_collision_result(OPX_COLLISION_RESULT_INIT), "result");
}

OPX_API opx_status opx_contact_init(opx_contact *contact, size_t size) {
    return init_struct(__func__, contact, size, opx_contact(OPX_CONTACT_INIT), "contact");
}

OPX_API opx_status opx_cost_box_init(opx_cost_box *box, size_t size) {
    return init_struct(__func__, box, size, opx_cost_box(OPX_COST_BOX_INIT), "box");
}

OPX_API opx_status opx_query_get_cost_box(const opx_query *query, size_t index, opx_cost_box *out_box) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_out_struct(out_box, "out_box");
        const std::vector<CostBox> &boxes = query->context.cost_boxes();
        if (index >= boxes.size())
            throw_invalid(format("index %zu is beyond the %zu cost boxes of the last query", index, boxes.size()));
        write_versioned(out_box, cost_box_to_abi(boxes[index], query->context.resolution()), "out_box");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_stats_init(opx_query_stats *stats, size_t size) {
    return init_struct(__func__, stats, size, opx_query_stats(OPX_QUERY_STATS_INIT), "stats");
}

OPX_API opx_status opx_query_get_stats(const opx_query *query, opx_query_stats *out_stats) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_out_struct(out_stats, "out_stats");
        const EngineStats s = query->context.stats();
        opx_query_stats stats = OPX_QUERY_STATS_INIT;
        stats.engine = engine_to_abi(query->context.engine_kind());
        stats.boxes = s.boxes, stats.builds = s.builds, stats.refine_steps_done = s.refine_steps_done;
        stats.sah_ratio = s.sah_ratio;
        stats.extract_ms = s.extract_ms, stats.build_ms = s.build_ms;
        write_versioned(out_stats, stats, "out_stats");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_create(const opx_query_options *options, opx_query **out) {
    if (out != nullptr) *out = nullptr;
    return guard(__func__, [&] {
        require_pointer(out, "out");
        opx_query_options merged = OPX_QUERY_OPTIONS_INIT;
        read_versioned(options, merged, "options");
        *out = std::make_unique<opx_query>(context_options(merged)).release();
        return OPX_OK;
    });
}

OPX_API void opx_query_destroy(opx_query *query) { delete query; }

OPX_API opx_status opx_query_collide(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                     const opx_collision_request *request,
                                     opx_collision_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        const SensorOctree *map = map_of(query, tree);
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_collision_request merged = OPX_COLLISION_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const CollisionSettings settings =
            map != nullptr ? collision_settings(merged, *map) : collision_settings_without_map(merged);
        const CollisionAnswer answer = query->context.collide(map, links->links, settings);
        write_versioned(out_result, collision_result_to_abi(answer, query->context), "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_get_contact(const opx_query *query, size_t index, opx_contact *out_contact) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_out_struct(out_contact, "out_contact");
        const std::vector<Contact> &cells = query->context.contacts();
        const std::vector<WorldContact> &objects = query->context.world_contacts();
        if (index >= cells.size() + objects.size())
            throw_invalid(format("index %zu is beyond the %zu contacts of the last query", index,
                                 cells.size() + objects.size()));
        const opx_contact contact = index < cells.size() ? contact_to_abi(cells[index])
                                                         : world_contact_to_abi(objects[index - cells.size()]);
        write_versioned(out_contact, contact, "out_contact");
        return OPX_OK;
    });
}

}  // extern "C"
