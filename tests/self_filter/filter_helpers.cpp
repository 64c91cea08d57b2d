#include "filter_helpers.hpp"

#include "real_support.hpp"

namespace filter_oracle {

opx_linkset *one_link(const opx_shape &shape, const opx_pose &pose) {
    opx_linkset *robot = nullptr;
    real::check_ok(opx_linkset_create(&robot), "opx_linkset_create");
    real::check_ok(opx_linkset_add_link(robot, "link", nullptr), "opx_linkset_add_link");
    real::check_ok(opx_linkset_add_shape(robot, 0, &shape, nullptr), "opx_linkset_add_shape");
    real::check_ok(opx_linkset_set_poses(robot, &pose, 1, 0), "opx_linkset_set_poses");
    return robot;
}

opx_insert_report insert_seen_from(opx_octree *tree, const FilterRequest &request, const Eigen::Vector3d &sensor,
                                   const std::vector<Eigen::Vector3d> &points) {
    std::vector<double> xyz;
    for (const Eigen::Vector3d &p : points)
        for (int a = 0; a < 3; ++a) xyz.push_back(p[a] - sensor[a]);
    opx_insert_options options = OPX_INSERT_OPTIONS_INIT;
    for (int a = 0; a < 3; ++a) options.sensor_pose.position[a] = sensor[a];
    options.robot = request.robot, options.robot_padding = request.robot_padding;
    options.clear_robot_volume = request.clear_robot_volume ? 1u : 0u;
    options.max_threads = request.max_threads;
    opx_insert_report r = OPX_INSERT_REPORT_INIT;
    real::check_ok(opx_octree_insert_points(tree, xyz.data(), points.size(), 0, OPX_SCALAR_FLOAT64, &options, &r),
                   "opx_octree_insert_points");
    return r;
}

std::vector<unsigned char> saved_bytes(const opx_octree *tree) {
    size_t size = 0;
    opx_octree_save_memory(tree, OPX_FORMAT_BT, nullptr, 0, &size);  // BUFFER_TOO_SMALL gives the size
    std::vector<unsigned char> bytes(size);
    real::check_ok(opx_octree_save_memory(tree, OPX_FORMAT_BT, bytes.data(), bytes.size(), &size), "save_memory");
    return bytes;
}

}  // namespace filter_oracle
