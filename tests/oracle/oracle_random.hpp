// Random robots for the oracle tests: shapes of the six kinds with random
// sizes, uniform random rotations, random paddings and disabled links.
// Deterministic: everything comes from one seeded generator.
#pragma once

#include "oracle_robot.hpp"

#include <cstdint>
#include <random>

namespace oracle {

class Rng {
public:
    explicit Rng(uint64_t seed) : engine_(seed) {}
    double uniform(double low, double high) { return std::uniform_real_distribution<double>(low, high)(engine_); }
    int integer(int low, int high) { return std::uniform_int_distribution<int>(low, high)(engine_); }
    bool chance(double p) { return uniform(0.0, 1.0) < p; }
    Vec3 point(const Vec3 &low, const Vec3 &high) {
        return Vec3(uniform(low.x(), high.x()), uniform(low.y(), high.y()), uniform(low.z(), high.z()));
    }

private:
    std::mt19937_64 engine_;
};

// Uniform over rotations (Shoemake), as x y z w.
Eigen::Quaterniond random_rotation(Rng &rng);
// A position in [low, high] and a uniform rotation, whose quaternion is now
// and then scaled (not unit: the library normalises it).
opx_pose random_pose(Rng &rng, const Vec3 &low, const Vec3 &high);

// A convex hull with known faces: a random tetrahedron, or a random linear
// image of an octahedron (a linear map keeps faces and convexity); `scale`
// bounds its extent.  A few interior points follow the hull vertices.
ShapeSpec random_convex(Rng &rng, double scale);
// A triangle soup, or the closed surface of a random convex hull.
ShapeSpec random_mesh(Rng &rng, double scale);
// A shape of `kind` whose extent is at most about `scale`, at a random pose
// in its link (sometimes the identity).
ShapeSpec random_shape(Rng &rng, int32_t kind, double scale);

struct RobotOptions {
    int min_links = 1, max_links = 6;
    int max_shapes_per_link = 3;
    double min_scale = 0.05, max_scale = 1.0;  // shape extents
    double max_padding = 0.2;                  // link and global
    double disabled_fraction = 0.15;
};

// Links with random shapes (all six kinds appear across links).
RobotSpec random_robot(Rng &rng, const RobotOptions &options);
// New random link poses in [low, high], paddings and enabled flags.
void randomize_state(Rng &rng, RobotSpec &robot, const RobotOptions &options, const Vec3 &low,
                     const Vec3 &high);

}  // namespace oracle
