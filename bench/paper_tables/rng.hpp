// Reproducible random numbers for the synthetic scenes.  std::mt19937_64
// is specified bit for bit by the standard, but the std:: distributions are
// not (libstdc++ and libc++ differ), so the uniform helpers are our own.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <random>

namespace paper_tables {

class Rng {
public:
    explicit Rng(uint64_t seed) : engine_(seed) {}

    // Uniform in [0, 1): the top 53 bits of one draw.
    double unit() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

    // Uniform in [low, high).
    double uniform(double low, double high) { return low + (high - low) * unit(); }

    // A point uniform in the cube [low, high)^3.
    std::array<double, 3> point_in_cube(double low, double high) {
        const double x = uniform(low, high);
        const double y = uniform(low, high);
        const double z = uniform(low, high);
        return {x, y, z};
    }

    // A rotation uniform over SO(3) as a unit quaternion x, y, z, w (ROS
    // order), by Shoemake's method ("Uniform random rotations", Graphics
    // Gems III, 1992).
    std::array<double, 4> rotation() {
        const double u1 = unit(), u2 = unit(), u3 = unit();
        const double two_pi = 6.283185307179586476925;
        const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
        return {a * std::sin(two_pi * u2), a * std::cos(two_pi * u2),
                b * std::sin(two_pi * u3), b * std::cos(two_pi * u3)};
    }

private:
    std::mt19937_64 engine_;
};

}  // namespace paper_tables
