// The synthetic scene of the paper's first experiment (section V): an
// occupancy octree of 7,784 random cells and 300 random objects (100
// spheres, 100 boxes, 100 cylinders) in the cube [-20, 20]^3 m.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include <octomap/OcTree.h>
#include <octoprox/octoprox.h>

#include "meshes.hpp"
#include "rng.hpp"

namespace paper_tables {

// Throws std::runtime_error naming `what` and opx_last_error() unless ok.
void check_opx(opx_status status, const char *what);

struct OctreeDeleter {
    void operator()(opx_octree *tree) const { opx_octree_destroy(tree); }
};
using OpxOctreePtr = std::unique_ptr<opx_octree, OctreeDeleter>;

// An identical copy of the map, read back from its .opx bytes: a new map
// to the library (nothing built from the original is reused for it).
OpxOctreePtr copy_octree(const opx_octree *tree);

struct SceneParameters {
    double half_extent = 20.0;  // the environment is [-half, half]^3 m
    double resolution = 0.2;    // m
    size_t occupied_cells = 7784;
    int objects_per_kind = 100;
    uint64_t octree_seed = 0x0C7012A1u;
    uint64_t object_seed = 0x0B1EC75u;
    uint64_t redraw_seed = 0x2ED2A3u;
};

enum class ObjectKind { kSphere, kBox, kCylinder };

// Variant (a): objects as primitives; (b): as triangle meshes.
enum class Variant { kPrimitives, kMeshes };
const char *variant_letter(Variant variant);

struct SceneObject {
    ObjectKind kind = ObjectKind::kSphere;
    double radius = 0.0;               // sphere, cylinder
    double length = 0.0;               // cylinder, full length along z
    std::array<double, 3> size{};      // box, full edges
    opx_pose pose = OPX_POSE_IDENTITY;  // in the map frame
};

// The mesh standing for an object in variant (b): a 16x16 UV sphere, a
// 16-sided closed cylinder, a 12-triangle box.
TriangleMesh object_mesh(const SceneObject &object);

// The same occupied cells in both libraries' octrees.
struct OccupancyMaps {
    OpxOctreePtr opx;
    std::shared_ptr<octomap::OcTree> octomap;
};

// Random single hits (OPX_INSERT_ENDPOINTS) into new cells until exactly
// `occupied_cells` leaves are occupied, then the same cells in OctoMap.
OccupancyMaps build_occupancy_maps(const SceneParameters &parameters);

// One object of `kind` with the scene's random sizes (m), identity pose.
SceneObject draw_shape(ObjectKind kind, Rng &rng);

// 100 spheres, 100 boxes, 100 cylinders with uniform poses, in that order.
std::vector<SceneObject> draw_objects(const SceneParameters &parameters, Rng &rng);

// A new uniform pose (position in the cube, rotation over SO(3)).
opx_pose draw_pose(const SceneParameters &parameters, Rng &rng);

// Number of occupied leaves of an OctoMap tree (by its own threshold).
size_t count_occupied_leaves(const octomap::OcTree &tree);

}  // namespace paper_tables
