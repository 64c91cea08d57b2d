// C shims: a caller's boxes as the map of an amortized context (a
// "collision map" from another source, paper IV.A).
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/request_checks.hpp"
#include "narrowphase/narrow_phase.hpp"
#include "query/cell_description.hpp"

#include <cmath>
#include <cstring>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

constexpr size_t kBoxBytes = 6 * sizeof(double);

void require_amortized(const opx_query *query) {
    if (query->engine != OPX_ENGINE_AMORTIZED)
        throw_invalid("query uses OPX_ENGINE_DIRECT; caller boxes need a context made with OPX_ENGINE_AMORTIZED");
}

void require_bound_boxes(const opx_query *query) {
    require_amortized(query);
    if (!query->amortized.holds_caller_boxes())
        throw_invalid("query holds no caller boxes (call opx_query_bind_boxes first; an octree query since "
                      "unbinds them)");
}

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

// occupancy_threshold and unknown_policy do not apply to boxes (checked
// for validity only, so one request serves octrees and boxes alike).
void check_shared_fields(int32_t unknown_policy, double threshold) {
    read_unknown_policy(unknown_policy, "request->unknown_policy");
    if (!(threshold == 0.0 || (threshold > 0.0 && threshold < 1.0)))
        throw_invalid(format("request->occupancy_threshold is %g; 0 or a probability in (0, 1) is needed", threshold));
}

CollisionSettings box_collision_settings(const opx_collision_request &r) {
    check_shared_fields(r.unknown_policy, r.occupancy_threshold);
    if (r.compute_cost) throw_invalid("request->compute_cost: caller boxes have no uncertain or unknown space");
    CollisionSettings s;
    s.max_contacts = r.max_contacts;
    s.penetration = r.compute_penetration != 0;
    return s;
}

DistanceSettings box_distance_settings(const opx_distance_request &r) {
    check_shared_fields(r.unknown_policy, r.occupancy_threshold);
    return read_distance_bounds(r);
}

opx_distance_result box_distance_to_abi(const DistanceOutcome &o, const DistanceSettings &s, const opx_query &q) {
    opx_distance_result out = OPX_DISTANCE_RESULT_INIT;
    out.found = o.found ? 1 : 0;
    out.narrow_tests = o.narrow_tests;
    out.distance = o.found ? o.distance : s.cutoff;
    if (!o.found) return out;
    const CellSummary cell = describe_caller_box(q.amortized.caller_box(static_cast<size_t>(o.box_index)));
    out.collided = o.distance <= kTouchTolerance ? 1 : 0;
    out.cell_class = cell.cell_class;
    out.link = o.link, out.shape = o.shape;
    for (int axis = 0; axis < 3; ++axis) {
        out.point_on_link[axis] = o.on_link[axis];
        out.point_on_cell[axis] = o.on_cell[axis];
        out.cell_center[axis] = cell.center[axis];
    }
    out.cell_size = cell.size;
    out.cell_probability = cell.probability;
    return out;
}

}  // namespace

extern "C" {

OPX_API opx_status opx_query_bind_boxes(opx_query *query, const double *boxes, size_t count, size_t stride) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_amortized(query);
        query->amortized.bind_boxes(read_boxes(boxes, count, stride));
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_collide_boxes(opx_query *query, const opx_linkset *links,
                                           const opx_collision_request *request, opx_collision_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_collision_request merged = OPX_COLLISION_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const CollisionSettings settings = box_collision_settings(merged);
        require_bound_boxes(query);
        const CollisionOutcome outcome = query->amortized.collide_boxes(links->links, settings, query->contacts);
        query->cost_boxes.clear();
        opx_collision_result result = OPX_COLLISION_RESULT_INIT;
        result.collided = outcome.collided ? 1 : 0;
        result.contact_count = query->contacts.size();
        result.truncated = outcome.truncated ? 1 : 0;
        result.narrow_tests = outcome.narrow_tests;
        write_versioned(out_result, result, "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_distance_boxes(opx_query *query, const opx_linkset *links,
                                            const opx_distance_request *request, opx_distance_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_distance_request merged = OPX_DISTANCE_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const DistanceSettings settings = box_distance_settings(merged);
        require_bound_boxes(query);
        query->link_distances.clear();
        const DistanceOutcome outcome = query->amortized.distance_boxes(
            links->links, settings, merged.per_link ? &query->link_distances : nullptr);
        write_versioned(out_result, box_distance_to_abi(outcome, settings, *query), "out_result");
        return OPX_OK;
    });
}

}  // extern "C"
