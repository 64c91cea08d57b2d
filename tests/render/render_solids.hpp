// Exact ray intersections with the solids of a link set, for the depth
// renderer (robot_render.hpp).  Each solid is held in the frame it is
// simplest in (a primitive in its shape frame, a mesh's triangles in the
// map frame); a ray is origin + t * dir, t > 0, in double throughout.
#pragma once

#include <octoprox/linkset.h>

#include <Eigen/Geometry>

#include <limits>
#include <vector>

namespace render {

using Vec3 = Eigen::Vector3d;

constexpr double kNoHit = std::numeric_limits<double>::infinity();

// A plane n . x <= offset bounding a convex hull (shape frame).
struct HalfSpace {
    Vec3 normal;
    double offset;
};

// One sphere, box, cylinder, capsule or convex hull, placed in the map.
struct Primitive {
    int32_t kind = 0;                 // OPX_SHAPE_*
    uint32_t link = 0;                // the link it belongs to (an attached object's link)
    Eigen::Isometry3d map_from_shape;  // the shape frame in the map frame
    double radius = 0.0;
    double half_length = 0.0;          // cylinder: half its length; capsule: half the segment
    Vec3 half_size = Vec3::Zero();     // box
    std::vector<HalfSpace> faces;      // convex: the hull's face planes
    std::vector<Vec3> corners;         // map frame: a set whose hull holds the solid
};

// A triangle in the map frame.
struct Triangle {
    Vec3 a, b, c;
};

// A mesh shape's triangles in the map frame.
struct Mesh {
    uint32_t link = 0;
    std::vector<Triangle> triangles;
};

// Every shape of every link and attached object (enabled or not) of a
// link set, read through the public C API, at its poses.  Throws
// std::runtime_error on a library error.
struct RobotSolids {
    std::vector<Primitive> primitives;
    std::vector<Mesh> meshes;
};
RobotSolids read_robot_solids(const opx_linkset *robot);

// The rigid transform of a pose (x y z qx qy qz qw).
Eigen::Isometry3d isometry(const opx_pose &pose);

// The primitive of `shape` (not a mesh) with its shape frame at
// `map_from_shape`.
Primitive make_primitive(const opx_shape &shape, const Eigen::Isometry3d &map_from_shape);

// The face planes of the convex hull of `points`: every plane through
// three of them that has all the others on one side (brute force, for
// the few vertices of a test's hull).
std::vector<HalfSpace> hull_faces(const std::vector<Vec3> &points);

// Whether `x` (map frame) lies inside the primitive (closed).
bool holds(const Primitive &solid, const Vec3 &x);

// The least t > 0 at which the ray enters the primitive, kNoHit when it
// misses.  A ray starting inside gives kNoHit (it enters nothing).
double first_hit(const Primitive &solid, const Vec3 &origin, const Vec3 &dir);

// The t > 0 at which the ray crosses the triangle, kNoHit when it does
// not (either side; edges included).
double triangle_hit(const Triangle &triangle, const Vec3 &origin, const Vec3 &dir);

}  // namespace render
