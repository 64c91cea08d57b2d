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


}  // namespace octoprox
