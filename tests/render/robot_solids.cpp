// read_robot_solids (render_solids.hpp): a link set's shapes through the
// public C API, placed in the map frame.
#include "render_solids.hpp"

#include <stdexcept>
#include <string>

namespace render {
namespace {

void check(opx_status status, const char *what) {
    if (status != OPX_OK) throw std::runtime_error(std::string(what) + ": " + opx_last_error());
}

void add_shape(RobotSolids &solids, uint32_t link, const opx_shape &shape, const Eigen::Isometry3d &map_from_parent) {
    const Eigen::Isometry3d map_from_shape = map_from_parent * isometry(shape.pose);
    if (shape.kind != OPX_SHAPE_MESH) {
        solids.primitives.push_back(make_primitive(shape, map_from_shape));
        solids.primitives.back().link = link;
        return;
    }
    const size_t stride = shape.vertex_stride == 0 ? 3 * sizeof(double) : shape.vertex_stride;
    const auto vertex = [&](uint32_t i) {
        const double *v = reinterpret_cast<const double *>(reinterpret_cast<const char *>(shape.vertices) + i * stride);
        return Vec3(map_from_shape * Vec3(v[0], v[1], v[2]));
    };
    Mesh mesh;
    mesh.link = link;
    for (size_t t = 0; t < shape.triangle_count; ++t) {
        const uint32_t *i = shape.indices + 3 * t;
        mesh.triangles.push_back({vertex(i[0]), vertex(i[1]), vertex(i[2])});
    }
    solids.meshes.push_back(std::move(mesh));
}

void add_links(RobotSolids &solids, const opx_linkset *robot) {
    uint32_t links = 0;
    check(opx_linkset_get_link_count(robot, &links), "opx_linkset_get_link_count");
    for (uint32_t link = 0; link < links; ++link) {
        uint32_t shapes = 0;
        opx_pose pose = OPX_POSE_IDENTITY;
        check(opx_linkset_get_shape_count(robot, link, &shapes), "opx_linkset_get_shape_count");
        check(opx_linkset_get_pose(robot, link, &pose), "opx_linkset_get_pose");
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            check(opx_linkset_get_shape(robot, link, s, &shape), "opx_linkset_get_shape");
            add_shape(solids, link, shape, isometry(pose));
        }
    }
}

// Attached objects: shape pose in the object frame, object in the link's.
void add_attached(RobotSolids &solids, const opx_linkset *robot) {
    uint32_t objects = 0;
    check(opx_linkset_get_attached_count(robot, &objects), "opx_linkset_get_attached_count");
    for (uint32_t object = 0; object < objects; ++object) {
        uint32_t link = 0, shapes = 0;
        opx_pose link_pose = OPX_POSE_IDENTITY, object_pose = OPX_POSE_IDENTITY;
        check(opx_linkset_get_attached_link(robot, object, &link), "opx_linkset_get_attached_link");
        check(opx_linkset_get_pose(robot, link, &link_pose), "opx_linkset_get_pose");
        check(opx_linkset_get_attached_pose(robot, object, &object_pose), "opx_linkset_get_attached_pose");
        check(opx_linkset_get_attached_shape_count(robot, object, &shapes), "opx_linkset_get_attached_shape_count");
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            check(opx_linkset_get_attached_shape(robot, object, s, &shape), "opx_linkset_get_attached_shape");
            add_shape(solids, link, shape, isometry(link_pose) * isometry(object_pose));
        }
    }
}

}  // namespace

Eigen::Isometry3d isometry(const opx_pose &pose) {
    const double *q = pose.orientation;  // x y z w
    Eigen::Isometry3d out = Eigen::Isometry3d::Identity();
    out.linear() = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
    out.translation() = Vec3(pose.position[0], pose.position[1], pose.position[2]);
    return out;
}

RobotSolids read_robot_solids(const opx_linkset *robot) {
    RobotSolids solids;
    add_links(solids, robot);
    add_attached(solids, robot);
    return solids;
}

}  // namespace render
