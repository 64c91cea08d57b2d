// The robot as the tests describe it (specs), its copy in the library (an
// opx_linkset built through the C ABI) and its placement in the map frame
// for the oracle (PlacedShape, computed here with Eigen, independently of
// the library).
#pragma once

#include "oracle_fcl.hpp"
#include "oracle_geometry.hpp"

#include <octoprox/octoprox.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace oracle {

// Prints what failed and the library's message, and exits 1, unless OPX_OK:
// for library calls that set up a test (an answer under test is compared,
// not required).
void require_ok(opx_status status, const char *what);

// The library's touch rule: a shape touches a cell when their distance is
// <= inflation + kTouchTolerance (closed sets, see query.h).
constexpr double kTouchTolerance = 1e-9;
// Half-width of the band around that threshold where an exact (polytope)
// decision is not compared: rounding of two independent computations.
constexpr double kExactAmbiguity = 1e-10;

struct ShapeSpec {
    int32_t kind = OPX_SHAPE_SPHERE;
    opx_pose pose = OPX_POSE_IDENTITY;  // shape frame in the link frame
    double radius = 0.0;
    double length = 0.0;
    Vec3 size = Vec3::Zero();   // box: full edges
    std::vector<Vec3> vertices; // convex: hull vertices first, then interior points; mesh
    size_t hull_vertex_count = 0;                   // convex: extreme points
    std::vector<std::array<int, 3>> hull_faces;     // convex: over the extreme points
                                                    // (none for 1..3 points: a point,
                                                    // a segment, a triangle)
    std::vector<std::array<uint32_t, 3>> triangles; // mesh
};

struct LinkSpec {
    std::string name;
    std::vector<ShapeSpec> shapes;
    double padding = 0.0;
    bool enabled = true;
    opx_pose pose = OPX_POSE_IDENTITY;  // link frame in the map frame
};

struct RobotSpec {
    std::vector<LinkSpec> links;
    double global_padding = 0.0;
};

// ---- the library's copy ----------------------------------------------------
// Adds every link and shape; aborts the test (exit 1) on a library error.
// Every other convex or mesh shape passes its vertices with a stride of 4
// doubles (the API's strided arrays).
opx_linkset *build_linkset(const RobotSpec &robot);
// Sends poses, paddings and enabled flags of `robot` to `links`.  `variant`
// varies the calls, which must not change the answers: bit 0 sends the poses
// before the paddings and flags (else after), bit 1 passes the poses in a
// strided array.
void update_linkset(opx_linkset *links, const RobotSpec &robot, unsigned variant = 0);

// ---- the oracle's placement ------------------------------------------------
struct PlacedShape {
    uint32_t link = 0, shape = 0;
    int32_t kind = OPX_SHAPE_SPHERE;
    double inflation = 0.0;  // radius of the ball added to the core
    Vec3 point = Vec3::Zero();  // sphere
    Segment segment;            // capsule
    OrientedBox box;            // box
    Cylinder cylinder;          // cylinder
    Polytope hull;              // convex
    std::vector<Triangle> triangles;  // mesh
    Vec3 bounds_min = Vec3::Zero(), bounds_max = Vec3::Zero();  // of the inflated shape
};

Eigen::Isometry3d isometry_of(const opx_pose &pose);
opx_pose pose_of(const Eigen::Isometry3d &transform);

// The shapes of the enabled links, in the map frame.
std::vector<PlacedShape> place_robot(const RobotSpec &robot);

// Distance between the shape's CORE (without inflation) and the cell.
// Pieces farther than `cutoff` may be skipped: the result is then only known
// to be > cutoff.
double shape_cell_distance(const PlacedShape &shape, const Cell &cell, double cutoff);

// Lower bound of the distance between the inflated shape's bounds and the cell.
double bounds_gap(const PlacedShape &shape, const Cell &cell);

enum class Verdict { kClear, kTouch, kAmbiguous };
Verdict judge(const PlacedShape &shape, double distance);

const char *kind_name(int32_t kind);
std::string describe_shape(const ShapeSpec &shape);
std::string describe_pose(const opx_pose &pose);

}  // namespace oracle
