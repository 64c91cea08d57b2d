#include "capi/request_checks.hpp"

#include "capi/error.hpp"

#include <octoprox/query.h>

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

}  // namespace octoprox::capi
