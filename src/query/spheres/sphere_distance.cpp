#include "query/spheres/sphere_distance.hpp"

#include "narrowphase/shape_pair.hpp"
#include "query/spheres/grid_nearest.hpp"
#include "query/spheres/map_nearest.hpp"
#include "query/spheres/sphere_grid.hpp"

#include <cmath>
#include <limits>

namespace octoprox {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The signed distance field of one part of the obstacles (the map, or the
// world's objects) at the centre.
struct PartDistance {
    bool found = false;
    double sdf = kInfinity;       // > 0 outside, <= 0 inside (closed sets)
    Vec3 witness = Vec3::Zero();  // the nearest obstacle point, or the nearest point outside
    Vec3 gradient = Vec3::Zero();
};

Vec3 unit(const Vec3 &v) { return v / v.norm(); }

// A centre on the map's obstacle surface: the normal of the faces that
// separate the obstacle box holding it from the free piece holding it
// (their sum, normalised, at an edge or corner).
Vec3 surface_normal(const Aabb &obstacle, const Aabb &free_piece) {
    Vec3 normal = Vec3::Zero();
    for (int axis = 0; axis < 3; ++axis) {
        if (free_piece.lo[axis] >= obstacle.hi[axis]) normal[axis] = 1.0;
        else if (free_piece.hi[axis] <= obstacle.lo[axis]) normal[axis] = -1.0;
    }
    if (normal.isZero()) normal = Vec3::UnitX();  // closed boxes that touch always have one; kept total
    return unit(normal);
}

PartDistance map_distance(const SensorOctree &tree, const ObstacleGrid *grid, const Vec3 &center, double bound,
                          const SphereSettings &settings) {
    PartDistance part;
    if (grid != nullptr && std::isfinite(bound) && sphere_surely_clear(*grid, center, bound)) return part;
    const OctreeView view = tree.view();
    // The grid holds whole cells: with extents the octree decides.
    const bool cells = grid != nullptr && !settings.point_extents;
    NearestPiece obstacle;
    const bool by_grid = cells && grid_nearest_obstacle(*grid, view.resolution(), center, bound * bound, obstacle);
    if (!by_grid) obstacle = nearest_obstacle(view, center, bound * bound, settings);
    if (!obstacle.found) return part;
    part.found = true;
    if (obstacle.squared > 0.0) {
        part.sdf = std::sqrt(obstacle.squared);
        part.witness = obstacle.point;
        part.gradient = unit(center - obstacle.point);
        return part;
    }
    const NearestPiece exit =
        by_grid ? grid_nearest_free(*grid, view.resolution(), center) : nearest_free(view, center, settings);
    part.sdf = -std::sqrt(exit.squared);
    part.witness = exit.point;
    part.gradient = exit.squared > 0.0 ? unit(exit.point - center) : surface_normal(obstacle.box, exit.box);
    return part;
}

// The centre as a shape: a ball of radius 0.
const PlacedShape &point_shape(const Vec3 &center) {
    thread_local PlacedShape point;
    point.kind = ShapeKind::kSphere;
    point.inflation = 0.0;
    point.core.kind = ConvexKind::kPoint;
    point.core.center = center;
    point.box = Aabb{center, center};
    return point;
}

// One object shape against the centre, into the world's best: nearer
// outside, or deeper inside (the first of equals stays).
void offer_shape(const PlacedShape &point, const PlacedShape &shape, PartDistance &best) {
    uint64_t tests = 0;
    const bool inside_known = best.found && best.sdf <= 0.0;
    const double bound = inside_known ? kTouchTolerance : best.sdf;
    ShapePairDistance d;
    if (!shape_pair_distance(point, shape, bound, d, tests)) return;
    if (d.distance > 0.0) {
        if (inside_known || !(d.distance < best.sdf)) return;
        best.found = true, best.sdf = d.distance, best.witness = d.on_b;
        best.gradient = unit(point.core.center - d.on_b);
        return;
    }
    const ShapePairPenetration p = shape_pair_penetration(point, shape, tests);
    if (inside_known && !(-p.depth < best.sdf)) return;
    best.found = true, best.sdf = -p.depth, best.witness = p.on_b;
    best.gradient = -p.normal;
}

PartDistance world_distance(const WorldIndex &index, const Vec3 &center, double bound,
                            std::vector<int32_t> &stack) {
    PartDistance best;
    best.sdf = bound;
    if (index.tree.empty()) return best;
    const PlacedShape &point = point_shape(center);
    const Aabb at{center, center};
    stack.assign(1, index.tree.root());
    while (!stack.empty()) {
        const int32_t i = stack.back();
        stack.pop_back();
        const AabbTreeNode &node = index.tree.node(i);
        const double squared = node.box.squared_distance(at);
        const bool inside_known = best.found && best.sdf <= 0.0;
        if (inside_known ? squared > 0.0 : !(squared < best.sdf * best.sdf)) continue;
        if (node.is_leaf()) {
            offer_shape(point, *index.shapes[node.item], best);
            continue;
        }
        stack.push_back(node.right);
        stack.push_back(node.left);
    }
    if (!best.found) best.sdf = kInfinity;
    return best;
}

// Inside some part: the deepest (the map first among equals); else the
// nearest.
const PartDistance &pick(const PartDistance &map, const PartDistance &world) {
    if (!world.found) return map;
    if (!map.found) return world;
    const bool map_in = map.sdf <= 0.0, world_in = world.sdf <= 0.0;
    if (map_in != world_in) return map_in ? map : world;
    return world.sdf < map.sdf ? world : map;
}

}  // namespace

SphereDistance sphere_distance(const SensorOctree *tree, const ObstacleGrid *grid, const WorldIndex *world,
                               const Vec3 &center, double radius, const SphereDistanceSettings &settings,
                               SphereDistanceScratch &scratch) {
    // Obstacle points at least this far from the centre leave the sphere
    // at max_distance or beyond.
    const double bound = radius + settings.max_distance;
    PartDistance map, objects;
    if (tree != nullptr) map = map_distance(*tree, grid, center, bound, settings.map);
    if (world != nullptr) objects = world_distance(*world, center, bound, scratch.stack);
    const PartDistance &best = pick(map, objects);
    SphereDistance out;
    out.distance = best.found ? best.sdf - radius : kInfinity;
    if (!(out.distance < settings.max_distance)) {
        out.distance = settings.max_distance;
        out.witness = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
        return out;
    }
    out.gradient = best.gradient;
    out.witness = best.witness;
    return out;
}

}  // namespace octoprox
