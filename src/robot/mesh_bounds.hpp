// Bounds of a mesh at a pose without placing its vertices: a pose update
// moves many meshes that no query then reaches.
#pragma once

#include "broadphase/aabb_tree.hpp"

#include <vector>

namespace octoprox {

// The boxes of the tree's nodes kFrontierDepth levels below the root (or
// the leaves above that depth): together they hold every item.
constexpr int kFrontierDepth = 4;

// A mesh's box after a pose update is the union of its placed frontier
// boxes, or, for a mesh of no more vertices than the frontier has boxes,
// the exact box of its placed vertices.
constexpr size_t kExactBoxVertices = size_t{1} << kFrontierDepth;
std::vector<Aabb> mesh_frontier_boxes(const AabbTree &tree);


}  // namespace octoprox
