// C shims: spheres against the map (spheres.h).
#include "capi/batch_inputs.hpp"
#include "capi/checks.hpp"
#include "capi/request_checks.hpp"
#include "capi/world_handle.hpp"
#include "query/batch/batch_split.hpp"
#include "query/spheres/sphere_distance.hpp"
#include "query/spheres/sphere_query.hpp"

#include <octoprox/spheres.h>

#include <cmath>
#include <cstring>

using namespace octoprox;
using namespace octoprox::capi;

namespace {

SphereSettings sphere_settings(const opx_sphere_request &r, const SensorOctree &tree) {
    SphereSettings s;
    s.unknown_occupied = read_unknown_policy(r.unknown_policy, "request->unknown_policy");
    s.threshold_log_odds = read_threshold_log_odds(r.occupancy_threshold, tree, "request->occupancy_threshold");
    s.point_extents = read_obstacle_geometry(r.obstacle_geometry, "request->obstacle_geometry");
    return s;
}

// Row i of the spheres, checked: a finite centre, a finite radius >= 0.
void read_sphere(const double *spheres, size_t stride, size_t i, Vec3 &center, double &radius) {
    double row[4];
    std::memcpy(row, reinterpret_cast<const unsigned char *>(spheres) + i * stride, sizeof row);
    for (double v : row)
        if (!std::isfinite(v)) throw_invalid(format("spheres row %zu holds a non-finite value", i));
    if (row[3] < 0.0) throw_invalid(format("spheres row %zu has radius %g; a radius >= 0 is needed", i, row[3]));
    center = Vec3(row[0], row[1], row[2]);
    radius = row[3];
}

size_t sphere_stride(size_t stride) {
    if (stride == 0) return 4 * sizeof(double);
    if (stride < 4 * sizeof(double))
        throw_invalid(format("stride %zu is below a row of 4 doubles (32 bytes); 0 means packed", stride));
    return stride;
}

SphereDistanceSettings sphere_distance_settings(const opx_sphere_distance_request &r, const SensorOctree *tree) {
    SphereDistanceSettings s;
    const CollisionSettings map = yes_no_settings(r.unknown_policy, r.occupancy_threshold, tree);
    s.map.unknown_occupied = map.unknown_occupied;
    s.map.threshold_log_odds = map.threshold_log_odds;
    s.map.point_extents = read_obstacle_geometry(r.obstacle_geometry, "request->obstacle_geometry");
    if (!(r.max_distance > 0.0))
        throw_invalid(format("request->max_distance is %g; a positive distance (+infinity: none) is needed",
                             r.max_distance));
    s.max_distance = r.max_distance;
    return s;
}

// The spheres' answers, split over the request's threads: each sphere is
// answered on its own, so the thread count never changes an answer.
void distance_rows(const SensorOctree *tree, const ObstacleGrid *grid, const World *world, const double *spheres,
                   size_t count, size_t stride, const SphereDistanceSettings &settings, uint32_t threads,
                   double *out_distance, double *out_gradient, double *out_witness) {
    const WorldIndex *index = nullptr;
    if (world != nullptr) {
        // The world's lazy parts are made here, on the caller's thread.
        index = &world->index();
        for (const PlacedShape *shape : index->shapes)
            if (shape->kind == ShapeKind::kMesh) shape->place_mesh();
    }
    const size_t tasks = task_count(threads, count);
    std::vector<SphereDistanceScratch> scratch(tasks);
    split_items(tasks, count, [&](size_t task, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            Vec3 center;
            double radius = 0.0;
            read_sphere(spheres, stride, i, center, radius);
            const SphereDistance d = sphere_distance(tree, grid, index, center, radius, settings, scratch[task]);
            out_distance[i] = d.distance;
            for (int axis = 0; axis < 3; ++axis) {
                if (out_gradient != nullptr) out_gradient[3 * i + axis] = d.gradient[axis];
                if (out_witness != nullptr) out_witness[3 * i + axis] = d.witness[axis];
            }
        }
    });
}

}  // namespace

extern "C" {

OPX_API opx_status opx_sphere_request_init(opx_sphere_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_sphere_request(OPX_SPHERE_REQUEST_INIT), "request");
}

OPX_API opx_status opx_query_collide_spheres(opx_query *query, const opx_octree *tree, const double *spheres,
                                             size_t count, size_t stride, const opx_sphere_request *request,
                                             uint8_t *out_collided, size_t capacity) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        require_pointer(tree, "tree");
        opx_sphere_request merged = OPX_SPHERE_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const SphereSettings settings = sphere_settings(merged, *tree->tree);
        require_rows(count, "count", capacity);
        require_pointer(spheres, "spheres");
        require_pointer(out_collided, "out_collided");
        stride = sphere_stride(stride);
        const ObstacleGrid *grid =
            settings.unknown_occupied ? nullptr : query->context.obstacle_grid(*tree->tree, settings.threshold_log_odds);
        for (size_t i = 0; i < count; ++i) {
            Vec3 center;
            double radius = 0.0;
            read_sphere(spheres, stride, i, center, radius);
            out_collided[i] = sphere_collides(*tree->tree, grid, center, radius, settings) ? 1 : 0;
        }
        return OPX_OK;
    });
}

OPX_API opx_status opx_sphere_distance_request_init(opx_sphere_distance_request *request, size_t size) {
    return init_struct(__func__, request, size, opx_sphere_distance_request(OPX_SPHERE_DISTANCE_REQUEST_INIT),
                       "request");
}

OPX_API opx_status opx_query_distance_spheres(opx_query *query, const opx_octree *tree, const double *spheres,
                                              size_t count, size_t stride,
                                              const opx_sphere_distance_request *request, double *out_distance,
                                              double *out_gradient, double *out_witness, size_t capacity) {
    return guard(__func__, [&] {
        require_pointer(query, "query");
        const SensorOctree *map = map_of(query, tree);
        opx_sphere_distance_request merged = OPX_SPHERE_DISTANCE_REQUEST_INIT;
        read_versioned(request, merged, "request");
        const SphereDistanceSettings settings = sphere_distance_settings(merged, map);
        require_rows(count, "count", capacity);
        require_pointer(spheres, "spheres");
        require_pointer(out_distance, "out_distance");
        stride = sphere_stride(stride);
        // Every row is checked before any is answered.
        for (size_t i = 0; i < count; ++i) {
            Vec3 center;
            double radius = 0.0;
            read_sphere(spheres, stride, i, center, radius);
        }
        const ObstacleGrid *grid = map == nullptr || settings.map.unknown_occupied
                                       ? nullptr
                                       : query->context.obstacle_grid(*map, settings.map.threshold_log_odds);
        distance_rows(map, grid, query->context.world(), spheres, count, stride, settings, merged.max_threads,
                      out_distance, out_gradient, out_witness);
        return OPX_OK;
    });
}

}  // extern "C"
