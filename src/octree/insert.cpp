// Sensor frame insertion with OctoMap's semantics (insertPointCloud): rays
// make cells more free, endpoints more occupied, each cell is updated once
// per frame and an endpoint wins over a ray.
#include "octree/sensor_octree.hpp"

#include "capi/error.hpp"

#include "octree/bounded_tree.hpp"
#include "octree/update_reserve.hpp"

#include <cmath>

namespace octoprox {
namespace {

bool is_finite(const Vec3 &p) { return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z()); }

// Filters the frame into map-frame float points, counting what is skipped.
octomap::Pointcloud usable_points(const SensorOctree &tree, const PointSource &points,
                                  const InsertSettings &settings, InsertCounts &counts) {
    const bool limited = settings.max_range > 0.0 && std::isfinite(settings.max_range);
    octomap::Pointcloud cloud;
    cloud.reserve(points.count);
    for (size_t i = 0; i < points.count; ++i) {
        const Vec3 p_sensor = points.read(i);
        if (!is_finite(p_sensor)) {
            ++counts.nonfinite;
            continue;
        }
        if (limited && p_sensor.norm() > settings.max_range) {
            ++counts.out_of_range;
            continue;
        }
        // OctoMap works in float: round once, then test the rounded point.
        const Vec3 p_map = settings.sensor_pose.apply(p_sensor);
        const octomap::point3d p(static_cast<float>(p_map.x()), static_cast<float>(p_map.y()),
                                 static_cast<float>(p_map.z()));
        if (!tree.contains(Vec3(p.x(), p.y(), p.z()))) {
            ++counts.outside_map;
            continue;
        }
        cloud.push_back(p);
    }
    counts.used = cloud.size();
    return cloud;
}

}  // namespace

InsertCounts SensorOctree::insert(const PointSource &points, const InsertSettings &settings) {
    const Vec3 &origin_map = settings.sensor_pose.translation;
    const octomap::point3d origin(static_cast<float>(origin_map.x()), static_cast<float>(origin_map.y()),
                                  static_cast<float>(origin_map.z()));
    if (settings.raycast && !contains(Vec3(origin.x(), origin.y(), origin.z())))
        throw_invalid("sensor_pose.position lies outside the map cube");

    InsertCounts counts;
    const octomap::Pointcloud cloud = usable_points(*this, points, settings, counts);
    octomap::KeySet free_cells, occupied_cells;
    if (settings.raycast) {
        tree_->computeUpdate(cloud, origin, free_cells, occupied_cells, -1.0);
    } else {
        for (const auto &p : cloud) occupied_cells.insert(tree_->coordToKey(p));
    }
    // Everything that may allocate happens above or here: the cell updates
    // below take their nodes from reserved blocks, so a frame goes into the
    // map whole or, out of memory, not at all.  (An empty map's root is made
    // by the first update, before any cell changes.)
    reserve_update(*tree_, free_cells, occupied_cells);
    ++generation_;
    // The same order as OctoMap's insertPointCloud, so the float log-odds
    // sums are identical.  The scope keeps the inner obstacle boxes.
    const BoundsScope scope(occupied_log_odds_);
    for (const auto &key : free_cells) tree_->updateNode(key, false, false);
    for (const auto &key : occupied_cells) tree_->updateNode(key, true, false);
    tree_->child_blocks().release_spares();
    grow_known_bounds(free_cells);
    grow_known_bounds(occupied_cells);
    counts.cells_missed = free_cells.size();
    counts.cells_hit = occupied_cells.size();
    return counts;
}

}  // namespace octoprox
