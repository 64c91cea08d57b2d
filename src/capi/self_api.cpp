// C shims: self-collision queries and the link pairs they check.
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "narrowphase/narrow_phase.hpp"
#include "query/self/pair_sampling.hpp"

#include <octoprox/self_collision.h>

#include <limits>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

void require_pair(const opx_linkset *links, uint32_t a, uint32_t b) {
    const size_t count = links->links.link_count();
    if (a >= count) throw_invalid(format("a: link %u does not exist (the set has %zu links)", a, count));
    if (b >= count) throw_invalid(format("b: link %u does not exist (the set has %zu links)", b, count));
    if (a == b) throw_invalid(format("a and b are both link %u; a pair is of two different links", a));
}

SelfDistanceSettings read_self_distance_request(const opx_self_distance_request &r) {
    if (std::isnan(r.cutoff) || r.cutoff < 0.0)
        throw_invalid(format("request->cutoff is %g; 0 (none) or a positive distance is needed", r.cutoff));
    SelfDistanceSettings s;
    s.cutoff = r.cutoff > 0.0 ? r.cutoff : std::numeric_limits<double>::infinity();
    s.signed_distance = r.signed_distance != 0;
    return s;
}

opx_self_collision_result collision_result_to_abi(const SelfCollisionOutcome &o, size_t contacts) {
    opx_self_collision_result out = OPX_SELF_COLLISION_RESULT_INIT;
    out.collided = o.collided ? 1 : 0;
    out.contact_count = contacts;
    out.truncated = o.truncated ? 1 : 0;
    out.link_pairs = o.link_pairs;
    out.narrow_tests = o.narrow_tests;
    return out;
}

opx_self_distance_result distance_result_to_abi(const SelfDistanceOutcome &o, double cutoff) {
    opx_self_distance_result out = OPX_SELF_DISTANCE_RESULT_INIT;
    out.found = o.found ? 1 : 0;
    out.link_pairs = o.link_pairs, out.narrow_tests = o.narrow_tests;
    out.distance = o.found ? o.distance : cutoff;
    if (!o.found) return out;
    out.collided = o.distance <= kTouchTolerance ? 1 : 0;  // the touch rule of collision queries
    out.link_a = o.link_a, out.shape_a = o.shape_a, out.link_b = o.link_b, out.shape_b = o.shape_b;
    out.attached_a = o.attached_a, out.attached_b = o.attached_b;
    for (int axis = 0; axis < 3; ++axis) out.point_on_a[axis] = o.on_a[axis], out.point_on_b[axis] = o.on_b[axis];
    return out;
}

opx_self_contact contact_to_abi(const SelfContact &c) {
    opx_self_contact out = OPX_SELF_CONTACT_INIT;
    out.link_a = c.link_a, out.shape_a = c.shape_a, out.link_b = c.link_b, out.shape_b = c.shape_b;
    out.attached_a = c.attached_a, out.attached_b = c.attached_b;
    out.depth = c.depth;
    for (int axis = 0; axis < 3; ++axis) out.normal[axis] = c.normal[axis], out.position[axis] = c.position[axis];
    return out;
}

}  // namespace

extern "C" {

OPX_API opx_status opx_self_collision_request_init(opx_self_collision_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_self_collision_request(OPX_SELF_COLLISION_REQUEST_INIT),
                       "request");
}

OPX_API opx_status opx_self_collision_result_init(opx_self_collision_result *result, size_t size) {
    return init_struct(__func__, result, size, opx_self_collision_result(OPX_SELF_COLLISION_RESULT_INIT), "result");
}

OPX_API opx_status opx_self_contact_init(opx_self_contact *contact, size_t size) {
    return init_struct(__func__, contact, size, opx_self_contact(OPX_SELF_CONTACT_INIT), "contact");
}

OPX_API opx_status opx_self_distance_request_init(opx_self_distance_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_self_distance_request(OPX_SELF_DISTANCE_REQUEST_INIT),
                       "request");
}

OPX_API opx_status opx_self_distance_result_init(opx_self_distance_result *result, size_t size) {
    return init_struct(__func__, result, size, opx_self_distance_result(OPX_SELF_DISTANCE_RESULT_INIT), "result");
}

OPX_API opx_status opx_pair_sampling_options_init(opx_pair_sampling_options *options, size_t size) {
    return init_struct(__func__, options, size, opx_pair_sampling_options(OPX_PAIR_SAMPLING_OPTIONS_INIT),
                       "options");
}

OPX_API opx_status opx_pair_sampling_result_init(opx_pair_sampling_result *result, size_t size) {
    return init_struct(__func__, result, size, opx_pair_sampling_result(OPX_PAIR_SAMPLING_RESULT_INIT), "result");
}

OPX_API opx_status opx_query_self_collide(opx_query *query, const opx_linkset *links,
                                          const opx_self_collision_request *request,
                                          opx_self_collision_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_self_collision_request merged = OPX_SELF_COLLISION_REQUEST_INIT;
        read_versioned(request, merged, "request");
        SelfCollisionSettings settings;
        settings.max_contacts = merged.max_contacts;
        settings.penetration = merged.compute_penetration != 0;
        const SelfCollisionOutcome outcome = query->context.self_collide(links->links, settings);
        const size_t contacts = query->context.self_contacts().size();
        write_versioned(out_result, collision_result_to_abi(outcome, contacts), "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_get_self_contact(const opx_query *query, size_t index, opx_self_contact *out_contact) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_out_struct(out_contact, "out_contact");
        const std::vector<SelfContact> &contacts = query->context.self_contacts();
        if (index >= contacts.size())
            throw_invalid(format("index %zu is beyond the %zu contacts of the last self-collision query", index,
                                 contacts.size()));
        write_versioned(out_contact, contact_to_abi(contacts[index]), "out_contact");
        return OPX_OK;
    });
}

OPX_API opx_status opx_query_self_distance(opx_query *query, const opx_linkset *links,
                                           const opx_self_distance_request *request,
                                           opx_self_distance_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(links, "links");
        require_out_struct(out_result, "out_result");
        opx_self_distance_request merged = OPX_SELF_DISTANCE_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const SelfDistanceSettings settings = read_self_distance_request(merged);
        const SelfDistanceOutcome outcome = query->context.self_distance(links->links, settings);
        write_versioned(out_result, distance_result_to_abi(outcome, settings.cutoff), "out_result");
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_set_pair_enabled(opx_linkset *links, uint32_t a, uint32_t b, int32_t enabled) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pair(links, a, b);
        links->links.set_pair_enabled(a, b, enabled != 0);
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_get_pair_enabled(const opx_linkset *links, uint32_t a, uint32_t b,
                                                int32_t *out_enabled) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        require_pointer(out_enabled, "out_enabled");
        require_pair(links, a, b);
        *out_enabled = links->links.pairs().enabled(a, b) ? 1 : 0;
        return OPX_OK;
    });
}

OPX_API opx_status opx_linkset_disable_never_colliding_pairs(opx_linkset *links,
                                                             const opx_pair_sampling_options *options,
                                                             opx_pair_sampling_result *out_result) {
    return guard(__func__, [&] {
        require_pointer(links, "links");
        if (out_result != nullptr) require_out_struct(out_result, "out_result");
        opx_pair_sampling_options merged = OPX_PAIR_SAMPLING_OPTIONS_INIT;
        read_versioned(options, merged, "options");
        if (links->robot.joints.empty())
            throw ApiError(OPX_ERROR_UNSUPPORTED, "links has no joints (not made from URDF): nothing to sample");
        PairSamplingSettings settings;
        settings.samples = merged.samples, settings.seed = merged.seed;
        settings.also_always = merged.also_always_colliding != 0;
        settings.also_now = merged.also_colliding_now != 0;
        const PairSamplingOutcome outcome = disable_never_colliding_pairs(links->links, links->robot.joints, settings);
        opx_pair_sampling_result result = OPX_PAIR_SAMPLING_RESULT_INIT;
        result.now = outcome.now, result.never = outcome.never, result.always = outcome.always;
        if (out_result != nullptr) write_versioned(out_result, result, "out_result");
        return OPX_OK;
    });
}

}  // extern "C"
