// Small helpers of the self-filter tests: maps, one-link robots, inserts
// of map-frame points seen from a sensor without rotation.
#pragma once

#include <octoprox/octoprox.h>

#include <Eigen/Dense>

#include <vector>

namespace filter_oracle {

// A robot of one link holding `shape`, the link at `pose`.
opx_linkset *one_link(const opx_shape &shape, const opx_pose &pose);

struct FilterRequest {
    const opx_linkset *robot = nullptr;
    double robot_padding = 0.0;
    bool clear_robot_volume = false;
    uint32_t max_threads = 1;
};

// The map's bytes in the .bt format.
std::vector<unsigned char> saved_bytes(const opx_octree *tree);
// Inserts `points` (map frame) seen from `sensor` (map frame), as float64
// offsets from it; fails the running cmocka test on an error.
opx_insert_report insert_seen_from(opx_octree *tree, const FilterRequest &request, const Eigen::Vector3d &sensor,
                                   const std::vector<Eigen::Vector3d> &points);

}  // namespace filter_oracle
