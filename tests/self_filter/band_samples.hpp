// Points on the surface of each solid kind with their outward normals, for
// the band-edge tests: a point at distance s along the normal from a
// surface point lies at distance s from a convex solid (its nearest point
// is the surface point); for a mesh that is not convex the test checks it
// with the oracle.
#pragma once

#include "filter_oracle.hpp"

#include <random>

namespace filter_oracle {

struct SurfacePoint {
    Vec3 point, normal;  // map frame
};

// A random point of the solid's surface (`solid` as the oracle reads it:
// a hull's or a closed mesh's triangles, outward) and its normal.
SurfacePoint random_surface_point(const Solid &solid, std::mt19937 &rng);

// A random rotation and position within `spread` of `centre`.
opx_pose random_pose(std::mt19937 &rng, const Vec3 &centre, double spread);

}  // namespace filter_oracle
