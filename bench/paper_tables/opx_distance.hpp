// Distance queries on the OctoProx side of the tables: the default request
// (exact, unknown space free, the octree's occupancy threshold).
#pragma once

#include <array>
#include <string>

#include <octoprox/octoprox.h>

#include "opx_pipelines.hpp"
#include "scene.hpp"

namespace paper_tables {

// The minimum distance between the link set and the occupied cells, in
// metres; 0 when some link touches one; +infinity when the map is empty.
double opx_min_distance(opx_query *query, const opx_octree *tree, const opx_linkset *links);

// A link set of one link holding one sphere of `radius` at its origin.
OpxLinksetPtr make_sphere_linkset(double radius);

// Moves the one link of a link set to `position` (identity rotation).
void move_single_link(opx_linkset *links, const std::array<double, 3> &position);

// A map loaded from a .bt or .ot file (default options); throws on failure.
OpxOctreePtr load_opx_octree(const std::string &path);

}  // namespace paper_tables
