// The FCL 0.7 side of the tables: the baseline pipeline of the paper
// (octree -> boxes -> dynamic AABB tree, as MoveIt did) and FCL's own
// octree collision (fcl::OcTree as one collision object).
#pragma once

#include <memory>
#include <vector>

#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/narrowphase/collision_object.h>
#include <octomap/OcTree.h>

#include "scene.hpp"

namespace paper_tables {

using FclManager = fcl::DynamicAABBTreeCollisionManagerd;
using FclObjectPtr = std::unique_ptr<fcl::CollisionObjectd>;
using FclGeometryPtr = std::shared_ptr<fcl::CollisionGeometryd>;

// A triangle mesh as an fcl::BVHModel<OBBRSS> (a surface, as in OctoProx).
FclGeometryPtr mesh_model(const TriangleMesh &mesh);

// An opx_pose (x y z, qx qy qz qw) as an FCL transform.
fcl::Transform3d to_transform(const opx_pose &pose);

// Collision objects together with the manager that points into them.
struct FclObjectSet {
    std::vector<FclObjectPtr> objects;
    std::unique_ptr<FclManager> manager;
};

// The robot: the scene's objects (primitives or BVHModel<OBBRSS> meshes)
// registered in a dynamic AABB tree, set up.
FclObjectSet make_fcl_object_set(const std::vector<SceneObject> &objects, Variant variant);

// ---- Pipeline "FCL boxes + DynamicAABBTree" ----------------------------

// T_{1,1}: one collision object per occupied leaf of the tree, found by
// iterating its leaves: an fcl::Box, or for variant (b) a 12-triangle
// BVHModel<OBBRSS>, at the cell centre.
std::vector<FclObjectPtr> boxes_from_octomap(const octomap::OcTree &tree, Variant variant);

// T_{1,2}: the boxes registered in a dynamic AABB tree, set up.
std::unique_ptr<FclManager> manage_objects(const std::vector<FclObjectPtr> &objects);

// T_q: robot manager against map manager, stopping at the first contact.
bool fcl_managers_collide(const FclManager &robot, FclManager &map);

// ---- Pipeline "FCL octree" --------------------------------------------

// T_{1,2}: the OctoMap tree wrapped as an fcl::OcTree collision object.
FclObjectPtr wrap_octree(const std::shared_ptr<const octomap::OcTree> &tree);

// T_q: robot manager against the octree object, stopping at the first contact.
bool fcl_octree_collides(const FclManager &robot, fcl::CollisionObjectd &octree);

// Cross-check: how many objects collide with the octree, one at a time.
size_t count_fcl_colliding_objects(const FclObjectSet &objects, const fcl::CollisionObjectd &octree);

}  // namespace paper_tables
