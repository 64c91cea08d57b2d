// What a ray walk starts from: OctoMap's per-axis face parameters for one
// ray (computeRayKeys' initialisation, operation for operation) and how a
// step along each axis moves the ray's bit in a FrameMarks.
#pragma once

#include "octree/frame_marks.hpp"

#include <octomap/OcTreeKey.h>
#include <octomap/octomap_types.h>

namespace octoprox {

class BoundedOcTree;

struct RaySetup {
    // The ray parameter (metres along the ray) of the next cell face on
    // each axis, the parameter between two faces, the key step (-1, 0, 1).
    double next_face[3];
    double face_spacing[3];
    int step[3];
    float length;  // the ray parameter of the end point
};

// What every ray of a frame shares: its origin and, per axis, the
// distance from the origin to the origin cell's face on either side
// ([axis][0] for the face a negative step crosses, [1] a positive one).
struct RayOrigin {
    octomap::point3d point;
    double to_face[3][2];
    double resolution;
};

RayOrigin ray_origin(const BoundedOcTree &tree, const octomap::OcTreeKey &origin_key,
                     const octomap::point3d &origin);

// OctoMap's computeRayKeys initialisation for origin -> end (keys differ).
RaySetup ray_setup(const RayOrigin &origin, const octomap::point3d &end);

// Four rays' RaySetup, lane by lane, as the walk's vectors load them.
struct alignas(32) RaySetupFour {
    double next_face[3][4];
    double face_spacing[3][4];
    double length[4];
    int64_t step[3][4];
};

// The same as ray_setup for four rays at once with AVX2
// (ray_setup_avx2.cpp), only where cpu_has_avx2() (base/avx2.hpp) says so.
void ray_setup_four(const RayOrigin &origin, const octomap::point3d *const ends[4], RaySetupFour &out);

// How one step along an axis moves the mark's bit: x + 8 y + 64 z inside
// a brick, the brick's index times 512 across bricks.
struct BitMoves {
    int64_t in_brick[3];      // staying inside the brick
    int64_t brick_change[3];  // added to that when entering the next brick
    uint64_t edge_mask[3];    // the bits of the in-brick coordinate along the axis
    uint64_t edge_value[3];   // their value where a step leaves the brick
};

BitMoves bit_moves(const int step[3], const FrameMarks &marks);

}  // namespace octoprox
