#include "pr2_fcl.hpp"

#include <stdexcept>
#include <string>

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>

#include "meshes.hpp"

namespace paper_tables {
namespace {

TriangleMesh copy_mesh(const opx_shape &shape) {
    TriangleMesh mesh;
    mesh.vertices.assign(shape.vertices, shape.vertices + 3 * shape.vertex_count);
    mesh.indices.assign(shape.indices, shape.indices + 3 * shape.triangle_count);
    return mesh;
}

// URDF gives only these four kinds (robot.h); anything else is a bug here.
FclGeometryPtr shape_geometry(const opx_shape &shape) {
    switch (shape.kind) {
    case OPX_SHAPE_SPHERE: return std::make_shared<fcl::Sphered>(shape.radius);
    case OPX_SHAPE_BOX: return std::make_shared<fcl::Boxd>(shape.size[0], shape.size[1], shape.size[2]);
    case OPX_SHAPE_CYLINDER: return std::make_shared<fcl::Cylinderd>(shape.radius, shape.length);
    case OPX_SHAPE_MESH: return mesh_model(copy_mesh(shape));
    default: throw std::runtime_error("FclRobot: unexpected shape kind " + std::to_string(shape.kind));
    }
}

}  // namespace

std::vector<opx_pose> link_poses(const opx_linkset *links) {
    uint32_t count = 0;
    check_opx(opx_linkset_get_link_count(links, &count), "opx_linkset_get_link_count");
    std::vector<opx_pose> poses(count, opx_pose(OPX_POSE_IDENTITY));
    for (uint32_t link = 0; link < count; ++link)
        check_opx(opx_linkset_get_pose(links, link, &poses[link]), "opx_linkset_get_pose");
    return poses;
}

FclRobot::FclRobot(const opx_linkset *links) {
    uint32_t count = 0;
    check_opx(opx_linkset_get_link_count(links, &count), "opx_linkset_get_link_count");
    for (uint32_t link = 0; link < count; ++link) {
        uint32_t shapes = 0;
        check_opx(opx_linkset_get_shape_count(links, link, &shapes), "opx_linkset_get_shape_count");
        for (uint32_t s = 0; s < shapes; ++s) {
            opx_shape shape = OPX_SHAPE_INIT;
            check_opx(opx_linkset_get_shape(links, link, s, &shape), "opx_linkset_get_shape");
            objects_.push_back(std::make_unique<fcl::CollisionObjectd>(shape_geometry(shape)));
            placements_.push_back({link, to_transform(shape.pose)});
        }
    }
    const std::vector<opx_pose> poses = link_poses(links);
    for (size_t i = 0; i < objects_.size(); ++i) {
        objects_[i]->setTransform(to_transform(poses[placements_[i].link]) * placements_[i].shape_in_link);
        objects_[i]->computeAABB();
    }
    manager_ = manage_objects(objects_);
}

void FclRobot::set_link_poses(const std::vector<opx_pose> &poses) {
    for (size_t i = 0; i < objects_.size(); ++i) {
        objects_[i]->setTransform(to_transform(poses[placements_[i].link]) * placements_[i].shape_in_link);
        objects_[i]->computeAABB();
    }
    manager_->update();
}

}  // namespace paper_tables
