// C shims' side of queries with a world: requests without an octree and
// the contacts with objects.
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/request_checks.hpp"
#include "capi/world_handle.hpp"

namespace octoprox::capi {
namespace {

void check_threshold(double threshold) {
    if (!(threshold == 0.0 || (threshold > 0.0 && threshold < 1.0)))
        throw_invalid(format("request->occupancy_threshold is %g; 0 (the octree's) or a probability strictly "
                             "between 0 and 1 is needed",
                             threshold));
}

}  // namespace

const SensorOctree *map_of(const opx_query *query, const opx_octree *tree) {
    if (tree != nullptr) return tree->tree.get();
    if (query->context.world() == nullptr)
        throw_invalid("tree is NULL (it may be NULL only when the query has a world: opx_query_set_world)");
    return nullptr;
}

CollisionSettings collision_settings_without_map(const opx_collision_request &r) {
    read_unknown_policy(r.unknown_policy, "request->unknown_policy");
    check_threshold(r.occupancy_threshold);
    if (r.compute_cost != 0)
        throw_invalid("request->compute_cost is 1 but tree is NULL: the cost of uncertain and unknown space needs "
                      "an octree");
    CollisionSettings settings;
    settings.max_contacts = r.max_contacts;
    settings.penetration = r.compute_penetration != 0;
    return settings;
}

CollisionSettings settings_for_map(const opx_collision_request &request, const SensorOctree *map) {
    return map != nullptr ? collision_settings(request, *map) : collision_settings_without_map(request);
}

DistanceSettings distance_settings_without_map(const opx_distance_request &r) {
    DistanceSettings settings = read_distance_bounds(r);
    read_unknown_policy(r.unknown_policy, "request->unknown_policy");
    check_threshold(r.occupancy_threshold);
    return settings;
}

opx_contact world_contact_to_abi(const WorldContact &c) {
    opx_contact out = OPX_CONTACT_INIT;
    out.link = c.link, out.shape = c.shape, out.attached = c.attached;
    out.object = static_cast<int32_t>(c.object), out.object_shape = c.object_shape;
    out.depth = c.depth;
    for (int axis = 0; axis < 3; ++axis) {
        out.normal[axis] = c.normal[axis];
        out.position[axis] = c.position[axis];
    }
    return out;
}

}  // namespace octoprox::capi
