// Signed distances of spheres to the map and the world's objects, with
// the gradient with respect to the centre and a witness point, for
// trajectory optimizers (spheres.h states the contract).
//
// A sphere's distance is sdf(centre) - radius, sdf being the signed
// distance field of the obstacles' union: outside, the distance to the
// nearest obstacle point (map_nearest.hpp); inside (closed sets), minus
// the distance to the nearest point outside every obstacle.
#pragma once

#include "octree/obstacle_grid.hpp"
#include "octree/sensor_octree.hpp"
#include "query/spheres/sphere_query.hpp"
#include "world/world.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

struct SphereDistanceSettings {
    SphereSettings map;
    double max_distance = 0.1;  // > 0, may be +infinity
};

struct SphereDistance {
    double distance = 0.0;
    Vec3 gradient = Vec3::Zero();  // unit, or zero when truncated
    Vec3 witness = Vec3::Zero();   // NaN when truncated
};

// What one thread reuses between spheres.
struct SphereDistanceScratch {
    std::vector<int32_t> stack;
};

// tree, grid and world may each be null.  grid: the map's obstacle grid
// for settings.map (unknown space free), which skips spheres surely beyond
// max_distance and, for whole cells, answers in place of the octree.
SphereDistance sphere_distance(const SensorOctree *tree, const ObstacleGrid *grid, const WorldIndex *world,
                               const Vec3 &center, double radius, const SphereDistanceSettings &settings,
                               SphereDistanceScratch &scratch);

}  // namespace octoprox
