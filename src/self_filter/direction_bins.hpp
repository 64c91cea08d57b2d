// Which of a few balls a ray from one origin may meet, by the ray's
// direction: a cube map of bins around the origin, each listing the balls
// whose cone of directions (seen from the origin) reaches the bin.  A ray
// whose bin lists nothing meets none of the balls, at about the cost of
// one division.
#pragma once

#include "geometry/pose.hpp"

#include <cstdint>
#include <vector>

namespace octoprox {

struct Ball {
    Vec3 center;
    double radius;
};

class DirectionBins {
public:
    static constexpr int kSide = 64;  // bins along a face's edge
    static constexpr int kBins = 6 * kSide * kSide;

    // Balls as seen from `origin`; a ball holding the origin (or touching
    // it) is listed in every bin.
    void build(const Vec3 &origin, const std::vector<Ball> &balls);

    // The balls a ray from the origin along `dir` (not zero) may meet:
    // indices into the balls given to build, in [*first, *last).
    void candidates(const Vec3 &dir, const uint32_t *&first, const uint32_t *&last) const {
        const uint32_t bin = bin_of(dir);
        first = ids_.data() + start_[bin];
        last = ids_.data() + start_[bin + 1];
    }

    // Balls listed in every bin (they hold the origin).
    const std::vector<uint32_t> &everywhere() const { return everywhere_; }

private:
    static uint32_t bin_of(const Vec3 &dir) {
        const double ax = dir.x() < 0 ? -dir.x() : dir.x(), ay = dir.y() < 0 ? -dir.y() : dir.y(),
                     az = dir.z() < 0 ? -dir.z() : dir.z();
        int axis = 0;
        double major = ax;
        if (ay > major) axis = 1, major = ay;
        if (az > major) axis = 2, major = az;
        const int face = 2 * axis + (dir[axis] < 0 ? 1 : 0);
        const double scale = 0.5 * kSide / major;
        const int u = clamp_bin(static_cast<int>((dir[(axis + 1) % 3] + major) * scale));
        const int v = clamp_bin(static_cast<int>((dir[(axis + 2) % 3] + major) * scale));
        return static_cast<uint32_t>((face * kSide + v) * kSide + u);
    }
    static int clamp_bin(int i) { return i < 0 ? 0 : (i >= kSide ? kSide - 1 : i); }

    std::vector<uint32_t> start_;  // kBins + 1 offsets into ids_
    std::vector<uint32_t> ids_;
    std::vector<uint32_t> everywhere_;
};

}  // namespace octoprox
