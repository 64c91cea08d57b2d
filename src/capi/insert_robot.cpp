// C shims' side of self-filtering: the robot of an insert's options made
// into the insert's ray clip and, when asked, the cells its volume clears.
#include "capi/handles.hpp"

#include "self_filter/padded_robot.hpp"
#include "self_filter/robot_volume.hpp"


namespace octoprox::capi {

InsertCounts run_insert(SensorOctree &tree, const PointSource &points, const InsertRequest &request) {
    InsertSettings settings = request.settings;
    CellRange bounds;
    if (request.use_bounds) {
        bounds = cell_range_of_box(request.bounds_min, request.bounds_max, tree.params().resolution);
        settings.bounds = &bounds;
    }
    if (request.robot == nullptr) return tree.insert(points, settings);
    const PaddedRobot robot(*request.robot, request.robot_padding, settings.sensor_pose.translation);
    std::vector<uint64_t> clear;
    if (request.clear_robot_volume) {
        clear = robot_volume_cells(robot, tree.params().resolution);
        settings.clear_cells = &clear;
    }
    settings.clip = &robot;
    return tree.insert(points, settings);
}

}  // namespace octoprox::capi
