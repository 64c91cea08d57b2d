// An exact depth renderer of a robot, for tests and benchmarks of
// self-filtering: what a depth camera would see of a link set's solids.
//
// The camera is a pinhole in the ROS optical frame (z forward, x right,
// y down).  Pixel (u, v) (column u, row v, 0-based, centres at integer
// coordinates) looks along the ray through ((u - cx) / fx, (v - cy) / fy, 1)
// in that frame, as opx_octree_insert_depth_image back-projects it.
//
// The solids are read through the public C API only (opx_linkset_get_shape,
// opx_linkset_get_pose, the attached objects' getters): every link's and
// attached object's shapes, enabled or not, UNPADDED, at the poses last
// set.  Sphere, box, cylinder, capsule and convex hull (its face planes)
// are intersected analytically; a mesh by its triangles (either side).
// All arithmetic is double; a depth is rounded to float once.  A solid
// that holds the camera's origin is not seen (a camera inside its
// housing); a mesh's triangles are seen from either side.  Surfaces nearer
// than 0.1 mm in depth are not seen (a near plane).
#pragma once

#include <octoprox/octoprox.h>

#include <cstddef>
#include <vector>

namespace render {

struct Camera {
    size_t width = 640, height = 480;
    double fx = 525.0, fy = 525.0, cx = 319.5, cy = 239.5;  // pixels
    opx_pose pose = OPX_POSE_IDENTITY;  // the optical frame in the map frame (x y z qx qy qz qw)
};

// A Kinect-class camera (640x480, fx = fy = 525, cx = 319.5, cy = 239.5)
// with its optical frame at `pose` in the map frame.
Camera kinect_camera(const opx_pose &pose);

// The pose of an optical frame at `eye` (map frame) looking at `target`,
// its image's "down" (optical y) as close to -`up` as the view allows.
opx_pose look_at(const double eye[3], const double target[3], const double up[3]);

// Depth along the optical z axis (metres) of the nearest robot surface per
// pixel, 0 where the ray meets nothing; width * height values, row after
// row.
std::vector<float> render_depth(const opx_linkset *robot, const Camera &camera);

// Per pixel the nearer nonzero depth of two images of the same size (0
// only where both are 0): a robot rendered into a scene's depth frame.
std::vector<float> nearer_depth(const std::vector<float> &a, const std::vector<float> &b);

// The point of pixel (u, v) at `depth` in the camera's optical frame, in
// double, as the library back-projects it before rounding.
void back_project(const Camera &camera, size_t u, size_t v, double depth, double out_xyz[3]);

}  // namespace render
