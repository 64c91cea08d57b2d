#include "pr2_scene.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "pcd_reader.h"
#include "report.hpp"
#include "timing.hpp"

namespace paper_tables {
namespace {

const char *const kFrameFile = "rgbd/frame_20121214T142255.814212_binary.pcd";
const char *const kUrdfFile = "robots/pr2_description/urdf/robot.xml";
const char *const kCameraLink = "wide_stereo_optical_frame";
constexpr double kHeadTilt = 0.82;  // rad: the frame's large flat surface becomes level (see demo_real.c)

struct Cloud {
    std::vector<float> xyz;  // packed, NaN points kept (the library skips them)
    size_t finite = 0;
};

Cloud read_frame() {
    const std::string path = data_root() + "/" + kFrameFile;
    pcd_cloud cloud;
    char error[600];
    if (pcd_read_file(path.c_str(), &cloud, error, sizeof error) != 0) throw std::runtime_error(error);
    Cloud out;
    out.xyz.assign(cloud.xyz, cloud.xyz + 3 * cloud.count);
    out.finite = cloud.finite_count;
    pcd_free(&cloud);
    return out;
}

OpxOctreePtr insert_frame(const Cloud &cloud, const opx_pose &sensor, double resolution) {
    opx_octree_options options = OPX_OCTREE_OPTIONS_INIT;
    options.resolution = resolution;
    opx_octree *raw = nullptr;
    check_opx(opx_octree_create(&options, &raw), "opx_octree_create");
    OpxOctreePtr tree(raw);
    opx_insert_options insert = OPX_INSERT_OPTIONS_INIT;
    insert.mode = OPX_INSERT_RAYCAST;
    insert.sensor_pose = sensor;
    check_opx(opx_octree_insert_points(tree.get(), cloud.xyz.data(), cloud.xyz.size() / 3, 0, OPX_SCALAR_FLOAT32,
                                       &insert, nullptr),
              "opx_octree_insert_points");
    return tree;
}

size_t occupied_count(const opx_octree *tree) {
    opx_octree_stats stats = OPX_OCTREE_STATS_INIT;
    check_opx(opx_octree_get_stats(tree, &stats), "opx_octree_get_stats");
    return stats.leaves_occupied;
}

bool is_mesh(const opx_shape &shape) { return shape.kind == OPX_SHAPE_MESH; }

}  // namespace

std::shared_ptr<octomap::OcTree> mirror_through_bt(const opx_octree *tree, double resolution) {
    size_t size = 0;
    opx_octree_save_memory(tree, OPX_FORMAT_BT, nullptr, 0, &size);  // BUFFER_TOO_SMALL gives the size
    std::string bytes(size, '\0');
    check_opx(opx_octree_save_memory(tree, OPX_FORMAT_BT, &bytes[0], bytes.size(), &size), "opx_octree_save_memory");
    std::istringstream stream(bytes);
    auto mirror = std::make_shared<octomap::OcTree>(resolution);
    if (!mirror->readBinary(stream)) throw std::runtime_error("octomap readBinary failed on OctoProx's .bt bytes");
    return mirror;
}

std::string data_root() {
    const char *env = std::getenv("OPX_DATA_DIR");
    return env != nullptr && env[0] != '\0' ? env : OPX_DEFAULT_DATA_DIR;
}

std::string missing_pr2_data() {
    for (const char *file : {kFrameFile, kUrdfFile}) {
        const std::string path = data_root() + "/" + file;
        if (!std::ifstream(path)) return path;
    }
    return "";
}

OpxLinksetPtr load_pr2() {
    const std::string urdf = data_root() + "/" + kUrdfFile;
    const std::string package = "moveit_resources_pr2_description=" + data_root() + "/robots/pr2_description";
    const char *dirs[1] = {package.c_str()};
    opx_urdf_options options = OPX_URDF_OPTIONS_INIT;
    options.package_dirs = dirs;
    options.package_dir_count = 1;
    opx_linkset *raw = nullptr;
    check_opx(opx_linkset_load_urdf_file(urdf.c_str(), &options, &raw), "opx_linkset_load_urdf_file");
    OpxLinksetPtr links(raw);
    const char *head = "head_tilt_joint";
    check_opx(opx_linkset_set_named_joint_positions(links.get(), &head, &kHeadTilt, 1, nullptr),
              "opx_linkset_set_named_joint_positions");
    return links;
}

RobotCounts count_robot(const opx_linkset *links) {
    RobotCounts counts;
    check_opx(opx_linkset_get_link_count(links, &counts.links), "opx_linkset_get_link_count");
    for (uint32_t link = 0; link < counts.links; ++link) {
        uint32_t shapes = 0, meshes = 0;
        check_opx(opx_linkset_get_shape_count(links, link, &shapes), "opx_linkset_get_shape_count");
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            check_opx(opx_linkset_get_shape(links, link, s, &shape), "opx_linkset_get_shape");
            meshes += is_mesh(shape);
            if (is_mesh(shape)) counts.mesh_triangles += static_cast<uint32_t>(shape.triangle_count);
        }
        counts.mesh_shapes += meshes;
        counts.primitive_shapes += shapes - meshes;
        if (shapes == 0) ++counts.empty_links;
        else if (meshes > 0) ++counts.mesh_links;
        else ++counts.primitive_links;
    }
    return counts;
}

opx_pose camera_pose(const opx_linkset *links) {
    uint32_t camera = 0;
    check_opx(opx_linkset_find_link(links, kCameraLink, &camera), "opx_linkset_find_link");
    opx_pose pose = OPX_POSE_IDENTITY;
    check_opx(opx_linkset_get_pose(links, camera, &pose), "opx_linkset_get_pose");
    return pose;
}

FrameMaps build_frame_maps(const opx_pose &sensor, const std::vector<double> &resolutions, size_t target_cells) {
    const Cloud cloud = read_frame();
    std::cout << "frame: " << kFrameFile << ", " << cloud.finite << " points with a return, inserted by ray casting "
              << "from the PR2's head camera (" << kCameraLink << ", head tilt " << kHeadTilt << " rad)\n";
    FrameMaps best;
    for (double resolution : resolutions) {
        OpxOctreePtr tree;
        const double ms = time_once_ms([&] { tree = insert_frame(cloud, sensor, resolution); });
        const size_t occupied = occupied_count(tree.get());
        std::cout << "  resolution " << resolution * 100.0 << " cm: " << occupied << " occupied cells (ingest "
                  << three_significant(ms) << " ms)\n";
        const auto gap = [&](size_t n) { return std::fabs(static_cast<double>(n) - static_cast<double>(target_cells)); };
        if (best.opx == nullptr || gap(occupied) < gap(best.occupied)) {
            best.resolution = resolution;
            best.occupied = occupied;
            best.opx = std::move(tree);
        }
    }
    best.octomap = mirror_through_bt(best.opx.get(), best.resolution);
    const size_t mirrored = count_occupied_leaves(*best.octomap);
    if (mirrored != best.occupied)
        throw std::runtime_error("the OctoMap mirror has " + std::to_string(mirrored) + " occupied leaves, OctoProx " +
                                 std::to_string(best.occupied));
    std::cout << "  chosen: " << best.resolution * 100.0 << " cm, " << best.occupied << " occupied cells (paper: "
              << target_cells << "); OctoMap reads the same map from its .bt bytes\n";
    return best;
}

}  // namespace paper_tables
