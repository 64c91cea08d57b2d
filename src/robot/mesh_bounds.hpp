// Bounds of a mesh at a pose without placing its vertices: a pose update
// moves many meshes that no query then reaches.
#pragma once

#include "broadphase/aabb_tree.hpp"

#include <vector>

namespace octoprox {

// Up to this many vertices a mesh's box after a pose update is the exact
// box of its placed vertices; above, the union of its placed frontier boxes.
constexpr size_t kExactBoxVertices = 256;

// The boxes of the tree's nodes kFrontierDepth levels below the root (or
// the leaves above that depth): together they hold every item.
constexpr int kFrontierDepth = 4;
std::vector<Aabb> mesh_frontier_boxes(const AabbTree &tree);

// How much larger the placed box of a mesh's shape-frame box (`local`,
// holding `vertices`) is than the exact box of its placed vertices: the
// ratio of their summed edge lengths, averaged over a fixed set of 24
// rotations (1: a box; about 1.5: a sphere).
double rotated_box_looseness(const Aabb &local, const std::vector<Vec3> &vertices);

// Up to this looseness a mesh may be bounded by its placed shape-frame box
// where a pose is checked once (MeshBox::kCheap): a few dozen flops in
// place of every vertex or frontier box.  Robot links (PR2: 1.10-1.36)
// pass; a sphere (1.48) keeps its tight box.
constexpr double kCheapBoxLooseness = 1.4;


}  // namespace octoprox
