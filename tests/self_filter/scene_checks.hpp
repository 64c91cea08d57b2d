// The checks one rendered frame goes through (scene_checks.cpp): the
// oracle's verdicts for its points, then at each resolution the library's
// self-filtered map against them (see test_self_filter_oracle.cpp).
#pragma once

#include "filter_scenes.hpp"

#include <string>

namespace filter_oracle {

struct SceneRun {
    std::string label;
    const opx_linkset *robot = nullptr;
    FilterSettings settings;
    double max_range = 1.3;  // metres, for the check with max_range
    FramePoints points;
    RenderedFrame rendered;
};

// Seconds spent, for the log.
struct SceneTimes {
    double oracle = 0.0, library = 0.0, octomap = 0.0;
};

// The checks beyond the maps at each resolution, each at the first one.
struct ExtraChecks {
    bool threads = true;      // max_threads 1, 2 and 0 give the same bytes and report
    bool max_range = true;    // the map with run.max_range
    bool depth_image = true;  // the depth-image path's report adds up
};

// Every check at each of `resolutions` (metres); fails the cmocka test on
// the first violation.
void check_scene(const SceneRun &run, const std::vector<double> &resolutions, const ExtraChecks &extra,
                 SceneTimes &times);

}  // namespace filter_oracle
