// The brute-force distance oracle: the minimum, over every obstacle cell and
// every placed (enabled) shape, of the exact distance between the PADDED
// shape and the cell, max(0, core distance - inflation).  Per shape, per
// link and overall.
//
// It is exhaustive in effect: for each shape every obstacle cell gets a lower
// bound (the gap between the cell and the padded shape's bounding box, which
// holds the padded shape); cells are then measured exactly in increasing
// order of that bound until the bound reaches the best distance found, so
// every cell that could be nearer has been measured.
#pragma once

#include "oracle_check.hpp"

#include <limits>
#include <vector>

namespace oracle {

constexpr double kNoDistance = std::numeric_limits<double>::infinity();

// Exact padded distance of one shape to one cell, and the core distance it
// comes from.  `doubt` is set when a cylinder distance needed FCL's
// arbitration by prism brackets (then only good to kCurvedAmbiguity).
struct PairDistance {
    double padded = kNoDistance;
    double core = kNoDistance;
    bool doubt = false;
};
PairDistance pair_distance(const PlacedShape &shape, const Cell &cell);

// Distance from a point to the shape's CORE (0 inside a solid; a mesh is its
// triangles).  The witness on a padded shape is at `inflation` from it.
double point_core_distance(const PlacedShape &shape, const Vec3 &point);

struct Nearest {
    double distance = kNoDistance;  // padded
    double core = kNoDistance;
    const PlacedShape *shape = nullptr;
    const MapCell *cell = nullptr;
    bool doubt = false;  // a cylinder near the minimum was arbitrated (see above)
};

struct NearestAnswer {
    Nearest overall;
    std::vector<Nearest> per_shape;  // parallel to the placed shapes
    std::vector<Nearest> per_link;   // one per link of the robot; none for disabled links
    uint64_t exact_pairs = 0;        // pairs measured exactly
};

// The obstacle cells of a map under one rule.
std::vector<const MapCell *> obstacle_cells(const CellIndex &cells, const ObstacleRule &rule);

NearestAnswer oracle_nearest(const std::vector<PlacedShape> &placed, size_t link_count,
                             const std::vector<const MapCell *> &obstacles);

}  // namespace oracle
