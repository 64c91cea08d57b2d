// The world handle of the C ABI (world.h) and the checks its shims share.
#pragma once

#include "query/collision_types.hpp"
#include "query/distance_types.hpp"
#include "query/world/world_collider.hpp"
#include "world/world.hpp"

#include <octoprox/world.h>

struct opx_world {
    octoprox::World world;
};

namespace octoprox {
class SensorOctree;
}

namespace octoprox::capi {

// `object` checked against the world's objects; throws invalid argument.
uint32_t require_object(const opx_world *world, uint32_t object);

// Caller boxes check no world objects: on a query with a world set they
// throw OPX_ERROR_UNSUPPORTED rather than answer for the boxes alone.
void refuse_world(const opx_query *query);

// The octree a collision or distance query reads: tree's, or null when
// tree is NULL and the query has a world (objects only).  Throws "tree is
// NULL" otherwise.
const SensorOctree *map_of(const opx_query *query, const opx_octree *tree);
// Requests of a query without an octree: every field is checked as for an
// octree; the map's fields (threshold, unknown policy) are not used, and
// compute_cost, which needs a map, is refused.
CollisionSettings collision_settings_without_map(const opx_collision_request &request);
DistanceSettings distance_settings_without_map(const opx_distance_request &request);
// collision_settings(request, *map), or collision_settings_without_map when
// map is null.
CollisionSettings settings_for_map(const opx_collision_request &request, const SensorOctree *map);

// The public form of a contact with a world object (cell fields zero).
opx_contact world_contact_to_abi(const WorldContact &contact);

}  // namespace octoprox::capi
