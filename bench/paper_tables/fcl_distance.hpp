// Distance queries on the FCL 0.7 side of the tables.  A broad phase
// (manager) hands pairs to a callback that runs fcl::distance on each and
// keeps the minimum; it stops as soon as the minimum reaches 0 (a pair
// touches), which is the early stop of scene H.  Every fcl::distance call
// asks for nearest points, with FCL's default GJK solver (libccd).
#pragma once

#include <memory>
#include <string>

#include <fcl/narrowphase/collision_object.h>
#include <octomap/OcTree.h>

#include "fcl_pipelines.hpp"

namespace paper_tables {

// FCL's default distance_tolerance: libccd's GJK stops when an iteration
// gains less than this, so curved shapes (cylinders) can be off by ~1e-6 m.
constexpr double kFclDefaultTolerance = 1e-6;

// Pipeline "FCL boxes + DynamicAABBTree": robot manager against the map
// manager.  Returns the minimum distance in metres, 0 when some pair
// touches or overlaps (FCL reports -1 for overlapping shapes).  A tighter
// distance_tolerance (1e-12) makes a referee for the cross-checks.
double fcl_managers_distance(const FclManager &robot, FclManager &map,
                             double distance_tolerance = kFclDefaultTolerance);

// Pipeline "FCL octree": robot manager against the fcl::OcTree object.
double fcl_octree_distance(const FclManager &robot, fcl::CollisionObjectd &octree);

// One pair, e.g. a sphere against an fcl::OcTree object; 0 when they touch.
double fcl_pair_distance(const fcl::CollisionObjectd &a, const fcl::CollisionObjectd &b);

// An fcl::Sphere collision object at the origin.
FclObjectPtr make_fcl_sphere(double radius);

// An OctoMap tree read from a .bt file with octomap's readBinary; throws
// std::runtime_error when the file cannot be read.
std::shared_ptr<octomap::OcTree> read_octomap_binary(const std::string &path);

}  // namespace paper_tables
