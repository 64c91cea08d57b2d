// The shared real data as a self-filtering scene: the real Kinect frame
// (rgbd/, 640x480 depth TIFF in millimetres, its intrinsics XML) seen from
// the PR2's head camera, with the PR2's arms rendered into it.
//
// Conventions of `opx-demo --real` and the benchmarks (bench/paper_tables
// pr2_scene): the PR2 from the shared URDF with its root link at the map
// origin, the head tilted down 0.82 rad (the frame's large flat surface
// becomes level), the frame taken by link wide_stereo_optical_frame.
//
// Data: $OPX_DATA_DIR, else the build's default (../shared/data).
#pragma once

#include "robot_render.hpp"

#include <string>
#include <vector>

namespace render {

// $OPX_DATA_DIR when set and not empty, else ../shared/data beside the
// source tree.
std::string data_dir();

// The first file the PR2 scene needs that is missing under `dir`, or ""
// when all are there.
std::string missing_pr2_data(const std::string &dir);

// The real depth frame in metres (0: no return), and its camera: the
// intrinsics of the file (fx = fy = 525, cx = 320, cy = 240), the pose
// left at identity.
struct RealFrame {
    Camera camera;
    std::vector<float> depth;
};
RealFrame load_real_frame(const std::string &dir);

// The robot rendered from `camera` into `scene_depth` (same size): the
// nearer surface per pixel.
std::vector<float> composite_robot(const opx_linkset *robot, const Camera &camera,
                                   const std::vector<float> &scene_depth);

// The PR2 at arm_pose; the camera (the real frame's intrinsics, the head
// camera's optical frame as pose); the real frame; and the composite of
// the robot's rendering into it.  Owns `robot`: destroy() it.
struct Pr2Scene {
    opx_linkset *robot = nullptr;
    Camera camera;
    std::vector<float> real_depth;
    std::vector<float> robot_depth;  // render_depth(robot, camera)
    std::vector<float> composite;    // nearer_depth(real_depth, robot_depth)
};

// How many arm configurations make_pr2_scene knows: 0 the right gripper
// on the table, 1 the left gripper just above it, 2 both arms low over
// it, 3 the right gripper just above it.
int pr2_arm_pose_count();

// The joints (names and positions) of configuration arm_pose: head tilt,
// both arms; joints not named stay 0.
void pr2_joint_positions(int arm_pose, std::vector<const char *> &names, std::vector<double> &positions);

// Throws std::runtime_error when a file is missing or unreadable.
Pr2Scene make_pr2_scene(const std::string &data_dir, int arm_pose);
void destroy(Pr2Scene &scene);

}  // namespace render
