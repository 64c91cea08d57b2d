// The map's nearest obstacle point to a point, and the nearest point
// outside every obstacle: the two halves of a signed distance to the
// union of the map's obstacle boxes (sphere_distance.hpp).
//
// Both are depth-first searches of the octree, children nearest first
// (ties by child index), pruned by the best distance so far; a piece
// replaces the best only when strictly nearer, so among equidistant
// pieces the first in that order wins, the same on every call.
//
// The obstacle boxes are those of the sphere checks (SphereSettings): an
// obstacle leaf's cube, or its point extent decoded without the collision
// queries' rounding pad (exact slot planes, the cube's own faces where the
// extent reaches them); unknown cubes with unknown_occupied.  Free space
// is everything else: non-obstacle leaves, unknown space when it is free,
// an extent leaf's cube outside its box, and all beyond the map cube.
#pragma once

#include "geometry/aabb.hpp"
#include "octree/octree_view.hpp"
#include "query/spheres/sphere_query.hpp"

#include <limits>

namespace octoprox {

// The squared distance from `at` to the closed box.
inline double squared_to(const Vec3 &at, const Aabb &box) {
    const Vec3 gap = (box.lo - at).cwiseMax(at - box.hi).cwiseMax(0.0);
    return gap.squaredNorm();
}

struct NearestPiece {
    bool found = false;
    double squared = std::numeric_limits<double>::infinity();  // from the point to `point`
    Vec3 point = Vec3::Zero();  // the nearest point of `box`
    Aabb box;                   // the obstacle box, or the free piece, holding it

    // Takes `box` when its nearest point to `at` is strictly nearer: the
    // first of equidistant pieces stays.
    void offer(const Vec3 &at, const Aabb &piece) {
        const double to_piece = squared_to(at, piece);
        if (!(to_piece < squared)) return;
        found = true;
        squared = to_piece;
        point = at.cwiseMax(piece.lo).cwiseMin(piece.hi);
        box = piece;
    }
};

// The nearest obstacle point strictly nearer than sqrt(bound_squared)
// (found = false: none).  squared 0: the point lies in an obstacle box
// (closed), the first one found.
NearestPiece nearest_obstacle(const OctreeView &view, const Vec3 &at, double bound_squared,
                              const SphereSettings &settings);

// The nearest point of the closure of free space (found is always true).
NearestPiece nearest_free(const OctreeView &view, const Vec3 &at, const SphereSettings &settings);

// An obstacle leaf's box under the settings (see above).
Aabb leaf_obstacle_box(const OctreeView &view, OctreeView::NodeRef node, const Aabb &cube,
                       const SphereSettings &settings);

}  // namespace octoprox
