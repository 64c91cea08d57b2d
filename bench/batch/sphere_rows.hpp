// The sphere rows of opx-bench-batch: the 50-sphere arm against the real
// frame at 2 cm through the batch call on one thread (ns per sphere), and
// one sphere per C call (ns per call), the two ways sphere-based planners
// ask: opx_query_collide_spheres with one sphere, and a one-sphere link set
// (set its pose, then opx_query_collide).
#pragma once

#include "configurations.hpp"

namespace batch_bench {

struct SphereArmTiming {
    double us_per_configuration = 0.0, ns_per_sphere = 0.0;
    double first_call_us = 0.0;  // one configuration on a new map (its obstacle grid built)
    size_t configurations = 0, collided = 0;
};

SphereArmTiming time_sphere_arm(Robot &arm, const Scene &scene, size_t count, int rounds);

struct SphereCallTiming {
    double ns_per_call = 0.0;
    // The first call on the map, which builds what later calls read (the
    // map's obstacle grid, or the link set's tree).
    double first_call_us = 0.0;
    size_t calls = 0, collided = 0;
};

// Spheres of 5 cm radius uniform in the box of the occupied cells, on a
// copy of the scene's map of their own (the first call builds its grid);
// `link_set`: through a one-sphere link set, else opx_query_collide_spheres.
SphereCallTiming time_single_sphere_calls(const Scene &scene, size_t count, int rounds, bool link_set);

}  // namespace batch_bench
