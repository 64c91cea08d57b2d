#include "oracle_min_distance.hpp"

#include <algorithm>
#include <utility>

namespace oracle {
namespace {

using Gap = std::pair<double, const MapCell *>;

double padded_distance(const PlacedShape &shape, const Cell &cell, double core_cutoff) {
    const double core = std::max(0.0, shape_cell_distance(shape, cell, core_cutoff));  // cylinders: -1 when deep
    return std::max(0.0, core - shape.inflation);
}

ExactMinimum shape_minimum(const PlacedShape &shape, const std::vector<const MapCell *> &obstacles) {
    std::vector<Gap> gaps;
    gaps.reserve(obstacles.size());
    for (const MapCell *cell : obstacles) gaps.push_back({bounds_gap(shape, cell->cell), cell});
    std::sort(gaps.begin(), gaps.end(), [](const Gap &a, const Gap &b) { return a.first < b.first; });
    ExactMinimum best;
    best.shape = &shape;
    for (const auto &[gap, cell] : gaps) {
        if (gap > best.distance || best.distance == 0.0) break;
        const double d = padded_distance(shape, cell->cell, best.distance + shape.inflation + 1e-6);
        if (d < best.distance) best.distance = d, best.cell = cell;
    }
    return best;
}

}  // namespace

std::vector<const MapCell *> obstacle_list(const CellIndex &cells, const ObstacleRule &rule) {
    std::vector<const MapCell *> out;
    for (const MapCell &cell : cells.cells())
        if (rule(cell)) out.push_back(&cell);
    return out;
}

ExactMinimum exact_min_distance(const std::vector<PlacedShape> &placed, const std::vector<const MapCell *> &obstacles) {
    ExactMinimum best, best_curved;
    for (const PlacedShape &shape : placed) {
        const ExactMinimum m = shape_minimum(shape, obstacles);
        ExactMinimum &slot = shape.kind == OPX_SHAPE_CYLINDER ? best_curved : best;
        if (m.distance < slot.distance) slot = m;
    }
    const bool curved_near = best_curved.distance <= best.distance + kCurvedDistanceTolerance;
    ExactMinimum answer = best_curved.distance < best.distance ? best_curved : best;
    answer.tolerance = curved_near ? kCurvedDistanceTolerance : kExactDistanceTolerance;
    return answer;
}

}  // namespace oracle
