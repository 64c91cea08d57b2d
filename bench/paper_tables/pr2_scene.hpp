// The scene of Table IV: the PR2 (the paper's robot, from the shared URDF)
// and an occupancy octree built from the shared real RGB-D frame, placed
// as in `opx-demo --real`: the frame is seen from the PR2's head camera
// (wide_stereo_optical_frame, head tilted down 0.82 rad), the robot's
// root link at the map origin.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <octomap/OcTree.h>
#include <octoprox/octoprox.h>

#include "opx_pipelines.hpp"
#include "scene.hpp"

namespace paper_tables {

// $OPX_DATA_DIR, else the build's default (../shared/data).
std::string data_root();

// The files Table IV needs under data_root(); empty when all exist, else
// the first missing path.
std::string missing_pr2_data();

// The PR2 loaded from the URDF (all links, all collision shapes), at FK
// with every joint 0 except the head tilt; the root link at the origin.
OpxLinksetPtr load_pr2();

// Links, and how many of them carry meshes, only primitives, or nothing.
struct RobotCounts {
    uint32_t links = 0, mesh_links = 0, primitive_links = 0, empty_links = 0;
    uint32_t mesh_shapes = 0, primitive_shapes = 0, mesh_triangles = 0;
};
RobotCounts count_robot(const opx_linkset *links);

// The head camera's pose (map frame) with the head tilted as in the demo.
opx_pose camera_pose(const opx_linkset *links);

// The same occupied cells in both libraries: OctoProx's map from the frame
// (ray casting, OPX_INSERT_RAYCAST), and OctoMap's read from its .bt bytes.
struct FrameMaps {
    double resolution = 0.0;
    size_t occupied = 0;
    OpxOctreePtr opx;
    std::shared_ptr<octomap::OcTree> octomap;
};

// OctoMap reads OctoProx's .bt bytes: the same leaves, occupied or free.
std::shared_ptr<octomap::OcTree> mirror_through_bt(const opx_octree *tree, double resolution);

// Builds the map at each candidate resolution and keeps the one whose
// occupied-cell count is closest to `target_cells`; prints the counts.
FrameMaps build_frame_maps(const opx_pose &sensor, const std::vector<double> &resolutions, size_t target_cells);

}  // namespace paper_tables
