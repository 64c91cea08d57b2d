// C shims: spheres against the map (spheres.h).
#include "capi/batch_inputs.hpp"
#include "capi/checks.hpp"
#include "capi/request_checks.hpp"
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
        if (stride == 0) stride = 4 * sizeof(double);
        else if (stride < 4 * sizeof(double))
            throw_invalid(format("stride %zu is below a row of 4 doubles (32 bytes); 0 means packed", stride));
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

}  // extern "C"
