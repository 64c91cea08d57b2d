// The maps and robots of opx-bench-batch.  Maps at 2 cm: the real RGB-D
// frame of the shared data seen from the PR2's head camera (as in Table IV
// and opx-frame-bench), and the generated room seen from its own camera;
// each as an OctoProx octree and, for FCL, the same cells as an OctoMap
// tree wrapped as an fcl::OcTree.  Robots: the PR2 (URDF with the full
// SRDF), the 7-joint primitive arm and the 50-sphere arm, the arms based at
// the PR2's right shoulder so that they reach into the same scene.
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "opx_pipelines.hpp"
#include "pr2_fcl.hpp"

namespace batch_bench {

constexpr double kResolution = 0.02;

struct Scene {
    std::string name;  // "real frame 2 cm" or "generated room 2 cm"
    paper_tables::OpxOctreePtr tree;
    std::shared_ptr<octomap::OcTree> octomap;
    paper_tables::FclObjectPtr fcl_octree;
    opx_pose robot_base = OPX_POSE_IDENTITY;  // the PR2's root link, map frame
    opx_pose arm_base = OPX_POSE_IDENTITY;    // the arms' base: the PR2's right shoulder there
    size_t occupied = 0;
};

using LinkPairs = std::vector<std::pair<uint32_t, uint32_t>>;

struct Robot {
    std::string name;  // "PR2", "arm 7", "sphere arm 50"
    paper_tables::OpxLinksetPtr links;
    std::unique_ptr<paper_tables::FclRobot> fcl;  // not for the sphere arm
    LinkPairs disabled;  // SRDF pairs (PR2), adjacent links (arms)
    size_t joints = 0;
    size_t shapes = 0;
};

// The PR2 with its SRDF, the head tilted as in Table IV.
Robot load_pr2();
Robot load_primitive_arm();
Robot load_sphere_arm();

// The scene with the PR2 (`pr2`, moved here) standing in it.
Scene real_scene(opx_linkset *pr2);
Scene room_scene(opx_linkset *pr2);

}  // namespace batch_bench
