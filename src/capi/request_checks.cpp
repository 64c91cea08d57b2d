#include "capi/request_checks.hpp"

#include "capi/error.hpp"

#include <cmath>
#include <limits>

namespace octoprox::capi {

bool read_unknown_policy(int32_t policy, const char *argument) {
    if (policy != OPX_UNKNOWN_FREE && policy != OPX_UNKNOWN_OCCUPIED)
        throw_invalid(format("%s %d is neither OPX_UNKNOWN_FREE (0) nor OPX_UNKNOWN_OCCUPIED (1)", argument, policy));
    return policy == OPX_UNKNOWN_OCCUPIED;
}

float read_threshold_log_odds(double threshold, const SensorOctree &tree, const char *argument) {
    if (!(threshold == 0.0 || (threshold > 0.0 && threshold < 1.0)))
        throw_invalid(format("%s is %g; 0 (the octree's) or a probability strictly between 0 and 1 is needed",
                             argument, threshold));
    return static_cast<float>(log_odds(threshold == 0.0 ? tree.params().occupied_threshold : threshold));
}

bool read_obstacle_geometry(int32_t geometry, const char *argument) {
    if (geometry != OPX_OBSTACLE_CELLS && geometry != OPX_OBSTACLE_POINT_EXTENTS)
        throw_invalid(format("%s %d is neither OPX_OBSTACLE_CELLS (0) nor OPX_OBSTACLE_POINT_EXTENTS (1)", argument,
                             geometry));
    return geometry == OPX_OBSTACLE_POINT_EXTENTS;
}

namespace {

void require_error_bound(double value, const char *argument) {
    if (!(value >= 0.0) || !std::isfinite(value))
        throw_invalid(format("%s is %g; a finite value >= 0 is needed", argument, value));
}

}  // namespace

DistanceSettings read_distance_bounds(const opx_distance_request &r) {
    require_error_bound(r.abs_err, "request->abs_err");
    require_error_bound(r.rel_err, "request->rel_err");
    if (std::isnan(r.cutoff) || r.cutoff < 0.0)
        throw_invalid(format("request->cutoff is %g; 0 (none) or a positive distance is needed", r.cutoff));
    DistanceSettings s;
    s.abs_err = r.abs_err, s.rel_err = r.rel_err;
    s.cutoff = r.cutoff > 0.0 ? r.cutoff : std::numeric_limits<double>::infinity();
    s.signed_distance = r.signed_distance != 0;
    return s;
}

}  // namespace octoprox::capi
