#include "query/cell_description.hpp"

#include "octree/sensor_octree.hpp"

namespace octoprox {

CellSummary describe_cell(const SensorOctree &tree, const CellKey &key, bool unknown, float log_odds) {
    CellSummary cell;
    const double resolution = tree.params().resolution;
    for (int axis = 0; axis < 3; ++axis) cell.center[axis] = key.center(axis, resolution);
    cell.size = key.size(resolution);
    cell.cell_class = unknown ? kUnknown : tree.classify_log_odds(log_odds);
    cell.probability = unknown ? 0.5 : probability_from_log_odds(log_odds);
    return cell;
}

CellSummary describe_caller_box(const Aabb &box) {
    CellSummary cell;
    cell.center = box.center();
    cell.size = box.longest_edge();
    cell.cell_class = kOccupied;
    cell.probability = 1.0;
    return cell;
}

void set_cell(Contact &contact, const CellSummary &cell) {
    for (int axis = 0; axis < 3; ++axis) contact.center[axis] = cell.center[axis];
    contact.size = cell.size;
    contact.cell_class = cell.cell_class;
    contact.probability = cell.probability;
}

void set_cell(DistanceOutcome &best, const CellKey &key, bool unknown, float log_odds) {
    best.cell = key;
    best.cell_unknown = unknown;
    best.cell_log_odds = unknown ? 0.0f : log_odds;
}

}  // namespace octoprox
