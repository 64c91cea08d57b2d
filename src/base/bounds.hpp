// The largest magnitude, in metres, of a length or a coordinate the library
// takes from a robot or a scene: URDF origins, sizes and mesh vertices,
// scene shapes' sizes, radii, lengths, poses and mesh vertices.  1,000 km is
// far beyond any robot or room, and small enough that sums and products
// over thousands of such values (a kinematic chain, a distance) stay finite.
#pragma once

namespace octoprox {

constexpr double kMaxMetres = 1e6;

}  // namespace octoprox
