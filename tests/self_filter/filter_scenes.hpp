// Rendered frames for the self-filter's oracle tests: a generated arm (no
// data needed) above a table, seen by a few cameras, and the frames'
// points in the map frame.
#pragma once

#include "expected_map.hpp"
#include "robot_render.hpp"

#include <string>
#include <vector>

namespace filter_oracle {

// A camera's composite frame: the robot rendered into a scene.
struct RenderedFrame {
    std::string label;
    render::Camera camera;
    std::vector<float> robot_depth, composite;
};

// The frame's pixels with a depth as points in the map frame (each pixel
// back-projected in double, moved by the camera pose in double, rounded to
// float once), the camera's origin rounded to float, and for each point
// whether its pixel shows the robot (the robot's depth is the composite's).
struct FramePoints {
    MapFrame frame;
    std::vector<bool> robot_pixel;
};
FramePoints frame_points(const RenderedFrame &rendered);

// The arm: links "shoulder" (cylinder), "upper" (capsule), "fore" (box),
// "wrist" (convex hull), "hand" (a closed L-shaped mesh, not convex) and
// "finger" (an open mesh: three faces of a tetrahedron), in configuration
// `configuration` (< arm_configuration_count()), with a box attached to
// the hand.  Poses set.
int arm_configuration_count();
opx_linkset *make_arm(int configuration);
// The shape of arm link `link` (0 to 5, in the order above), in the link
// frame; its vertices and indices stay valid.
opx_shape arm_link_shape(int link);

// A table whose top lies 1 cm above the arm's lowest corner and a wall
// behind it, as a link set to render.
opx_linkset *make_environment(const opx_linkset *arm);

// Cameras (320x240, fx = fy = 262.5) looking at the arm from around it,
// and one from inside the shoulder's cylinder.
std::vector<render::Camera> arm_cameras();

// The robot rendered from `camera` into the environment's rendering.
RenderedFrame render_frame(const std::string &label, const opx_linkset *robot, const opx_linkset *environment,
                           const render::Camera &camera);

}  // namespace filter_oracle
