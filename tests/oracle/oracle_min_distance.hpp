// The exact minimum distance between placed (enabled) shapes, padding
// included, and a set of obstacle cells: max(0, core distance - inflation)
// minimised over every pair.  Each shape measures the cells in increasing
// order of a lower bound (the gap between its padded bounding box and the
// cell) until that bound passes its best distance, so no nearer cell is
// left out.
#pragma once

#include "oracle_check.hpp"

#include <limits>
#include <vector>

namespace oracle {

// Comparison tolerances of a distance: exact pairs, and pairs decided by a
// cylinder (GJK on a curved surface, and FCL in the oracle).
constexpr double kExactDistanceTolerance = 1e-9;
constexpr double kCurvedDistanceTolerance = 1e-6;

struct ExactMinimum {
    double distance = std::numeric_limits<double>::infinity();  // padded, >= 0
    const PlacedShape *shape = nullptr;
    const MapCell *cell = nullptr;
    // kCurvedDistanceTolerance when a cylinder pair lies within it of the
    // minimum, else kExactDistanceTolerance.
    double tolerance = kExactDistanceTolerance;
};

// The obstacle cells of the map under one rule.
std::vector<const MapCell *> obstacle_list(const CellIndex &cells, const ObstacleRule &rule);

ExactMinimum exact_min_distance(const std::vector<PlacedShape> &placed, const std::vector<const MapCell *> &obstacles);

}  // namespace oracle
