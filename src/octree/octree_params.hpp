// Parameters of a sensor octree (mirrors opx_octree_options).
#pragma once

#include <cmath>

namespace octoprox {

struct OctreeParams {
    double resolution = 0.05;
    double prob_hit = 0.7;
    double prob_miss = 0.4;
    double clamp_min = 0.1192;
    double clamp_max = 0.971;
    double occupied_threshold = 0.5;
    double free_threshold = 0.5;
};

// The cell edges a map may have, in metres.  Outside them OctoMap's key
// arithmetic overflows (a denormal resolution makes 1/resolution infinite)
// or the map's 2^16 cells per axis mean nothing physical.
constexpr double kMinResolution = 1e-6;
constexpr double kMaxResolution = 1e6;
inline bool resolution_in_range(double resolution) {
    return resolution >= kMinResolution && resolution <= kMaxResolution;  // false for NaN
}

// Throws ApiError(INVALID_ARGUMENT) naming the first bad field of `argument`.
void validate_params(const OctreeParams &params, const char *argument);

inline double log_odds(double probability) { return std::log(probability / (1.0 - probability)); }
// OctoMap's formula, so probabilities are bit-identical to OctoMap's.
inline double probability_from_log_odds(double log_odds) { return 1.0 - 1.0 / (1.0 + std::exp(log_odds)); }

}  // namespace octoprox
