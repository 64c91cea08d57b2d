// C shims: query contexts and collision queries.
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/request_checks.hpp"

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

}  // namespace octoprox::capi

namespace octoprox::capi {

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

}  // namespace octoprox::capi

namespace {

opx_contact contact_to_abi(const Contact &c) {
    return opx_contact{sizeof(opx_contact), c.link, c.shape, c.cell_class,
                       {c.center[0], c.center[1], c.center[2]}, c.size, c.probability, c.depth,
                       {c.normal[0], c.normal[1], c.normal[2]}, {c.position[0], c.position[1], c.position[2]}};
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
        if (index >= query->cost_boxes.size())
            throw_invalid(format("index %zu is beyond the %zu cost boxes of the last query", index,
                                 query->cost_boxes.size()));
        write_versioned(out_box, cost_box_to_abi(query->cost_boxes[index], query->resolution), "out_box");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_stats_init(opx_query_stats *stats, size_t size) {
    return init_struct(__func__, stats, size, opx_query_stats(OPX_QUERY_STATS_INIT), "stats");
}

OPX_API opx_status opx_query_get_stats(opx_query *query, opx_query_stats *out_stats) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_out_struct(out_stats, "out_stats");
        opx_query_stats stats = OPX_QUERY_STATS_INIT;
        stats.engine = query->engine;
        if (query->engine == OPX_ENGINE_AMORTIZED) {
            const AmortizedStats s = query->amortized.stats();
            stats.boxes = s.boxes, stats.builds = s.builds, stats.refine_steps_done = s.refine_steps_done;
            stats.sah_ratio = query->amortized.sah_ratio();
            stats.extract_ms = s.extract_ms, stats.build_ms = s.build_ms;
        }
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
        if (merged.engine != OPX_ENGINE_DIRECT && merged.engine != OPX_ENGINE_AMORTIZED)
            throw_invalid(format("options->engine %d is neither OPX_ENGINE_DIRECT (1) nor OPX_ENGINE_AMORTIZED (2)",
                                 merged.engine));
        if (merged.morton_bits < 1 || merged.morton_bits > 21)
            throw_invalid(format("options->morton_bits %u is outside 1..21", merged.morton_bits));
        auto query = std::make_unique<opx_query>();
        query->engine = merged.engine;
        AmortizedOptions amortized;
        amortized.refine_steps = merged.refine_steps;
        amortized.morton_bits = static_cast<int>(merged.morton_bits);
        query->amortized = AmortizedEngine(amortized);
        *out = query.release();
        return OPX_OK;
    });
}

OPX_API void opx_query_destroy(opx_query *query) { delete query; }

OPX_API opx_status opx_query_collide(opx_query *query, const opx_octree *tree, const opx_linkset *links,
                                     const opx_collision_request *request,
                                     opx_collision_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(tree, "tree");
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_collision_request merged = OPX_COLLISION_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const CollisionSettings settings = collision_settings(merged, *tree->tree);
        query->resolution = tree->tree->params().resolution;
        const bool amortized = query->engine == OPX_ENGINE_AMORTIZED;
        const CollisionOutcome outcome =
            amortized ? query->amortized.collide(*tree->tree, links->links, settings, query->contacts)
                      : query->direct.collide(*tree->tree, links->links, settings, query->contacts);
        CostCollector &cost_pairs = amortized ? query->amortized.cost() : query->direct.cost();
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        result.collided = outcome.collided ? 1 : 0;
        result.contact_count = query->contacts.size();
        result.truncated = outcome.truncated ? 1 : 0;
        result.narrow_tests = outcome.narrow_tests;
        query->cost_boxes.clear();
        if (settings.cost) {
            link_boxes(links->links, cost_pairs, query->link_boxes);
            const CostSummary cost = cost_pairs.finish(query->link_boxes, settings.max_cost_boxes, query->cost_boxes);
            result.total_cost = cost.total;
            result.cost_boxes_found = cost.box_count;
            result.cost_box_count = query->cost_boxes.size();
        }
        write_versioned(out_result, result, "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_get_contact(const opx_query *query, size_t index, opx_contact *out_contact) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_out_struct(out_contact, "out_contact");
        if (index >= query->contacts.size())
            throw_invalid(format("index %zu is beyond the %zu contacts of the last query", index,
                                 query->contacts.size()));
        write_versioned(out_contact, contact_to_abi(query->contacts[index]), "out_contact");
        return OPX_OK;
    });
}

}  // extern "C"
