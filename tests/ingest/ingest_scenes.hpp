// Sensor frames for the ingest tests: each is a sensor origin and points in
// the map frame (floats, as OctoMap takes them), built so that the points
// in the sensor frame (map point - origin, in double) are exact.
#pragma once

#include <octomap/octomap_types.h>

#include <cstdint>
#include <random>
#include <vector>

namespace ingest {

struct Frame {
    octomap::point3d origin;
    std::vector<octomap::point3d> points;  // map frame
};

// Points scattered in a box around the origin, some far, some outside the
// map when `outside` is set.
Frame random_frame(std::mt19937 &rng, float spread, size_t count, bool outside);
// A 640x480 depth camera in a 6 m x 6 m x 2.5 m room with a table: every
// ray ends on a wall, the floor, the ceiling or the table.
Frame room_frame(const octomap::point3d &origin, float yaw);
// Ties: an origin on a cell corner, on a face and at a centre, points on
// cell faces, edges and corners, rays along the axes and the diagonals.
Frame tie_frame(double resolution, int variant);
// Dense rows of points a quarter cell apart on planes, as a depth camera
// gives them: many rays ending in each cell, on its faces, edges and
// corners, one after another.
Frame dense_frame(double resolution, int variant);

}  // namespace ingest
