// Fewer points with the same convex hull: a robot's open mesh is filtered
// as the hull of its vertices, and GJK's support search reads every point
// it is given at each step.
#pragma once

#include "geometry/aabb.hpp"

#include <vector>

namespace octoprox {

// A subset of `points` holding every vertex of their convex hull (so the
// same hull): the points strictly inside the polytope of the extreme
// points in 64 directions are left out.  Small sets come back whole.
std::vector<Vec3> hull_vertex_superset(const std::vector<Vec3> &points);

}  // namespace octoprox
