#include "fcl_pipelines.hpp"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/octree/octree.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>

namespace paper_tables {

FclGeometryPtr mesh_model(const TriangleMesh &mesh) {
    std::vector<fcl::Vector3d> points;
    points.reserve(mesh.vertex_count());
    for (size_t i = 0; i < mesh.vertex_count(); ++i)
        points.emplace_back(mesh.vertices[3 * i], mesh.vertices[3 * i + 1], mesh.vertices[3 * i + 2]);
    std::vector<fcl::Triangle> triangles;
    triangles.reserve(mesh.triangle_count());
    for (size_t i = 0; i < mesh.triangle_count(); ++i)
        triangles.emplace_back(mesh.indices[3 * i], mesh.indices[3 * i + 1], mesh.indices[3 * i + 2]);
    auto model = std::make_shared<fcl::BVHModel<fcl::OBBRSSd>>();
    model->beginModel(static_cast<int>(triangles.size()), static_cast<int>(points.size()));
    model->addSubModel(points, triangles);
    model->endModel();
    return model;
}

fcl::Transform3d to_transform(const opx_pose &pose) {
    const double *q = pose.orientation;
    fcl::Transform3d transform = fcl::Transform3d::Identity();
    transform.linear() = Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized().toRotationMatrix();
    transform.translation() = fcl::Vector3d(pose.position[0], pose.position[1], pose.position[2]);
    return transform;
}

namespace {

using GeometryPtr = FclGeometryPtr;

GeometryPtr primitive_geometry(const SceneObject &object) {
    switch (object.kind) {
    case ObjectKind::kSphere: return std::make_shared<fcl::Sphered>(object.radius);
    case ObjectKind::kBox: return std::make_shared<fcl::Boxd>(object.size[0], object.size[1], object.size[2]);
    case ObjectKind::kCylinder: return std::make_shared<fcl::Cylinderd>(object.radius, object.length);
    }
    return nullptr;
}

GeometryPtr object_geometry(const SceneObject &object, Variant variant) {
    return variant == Variant::kPrimitives ? primitive_geometry(object) : mesh_model(object_mesh(object));
}

GeometryPtr cell_geometry(double edge, Variant variant) {
    if (variant == Variant::kPrimitives) return std::make_shared<fcl::Boxd>(edge, edge, edge);
    return mesh_model(make_box(edge, edge, edge));
}

fcl::Transform3d translation(double x, double y, double z) {
    fcl::Transform3d transform = fcl::Transform3d::Identity();
    transform.translation() = fcl::Vector3d(x, y, z);
    return transform;
}

// The callback's state: one request (one contact), a flag to stop.
struct FirstContact {
    fcl::CollisionRequestd request;
    bool done = false;
};

// FCL's default callback, reduced: exact test of the pair, stop (return
// true) at the first contact.
bool stop_at_first_contact(fcl::CollisionObjectd *a, fcl::CollisionObjectd *b, void *data) {
    auto *state = static_cast<FirstContact *>(data);
    if (state->done) return true;
    fcl::CollisionResultd result;
    fcl::collide(a, b, state->request, result);
    state->done = result.isCollision();
    return state->done;
}

}  // namespace

FclObjectSet make_fcl_object_set(const std::vector<SceneObject> &objects, Variant variant) {
    FclObjectSet set;
    for (const SceneObject &object : objects)
        set.objects.push_back(std::make_unique<fcl::CollisionObjectd>(object_geometry(object, variant),
                                                                      to_transform(object.pose)));
    set.manager = manage_objects(set.objects);
    return set;
}

std::vector<FclObjectPtr> boxes_from_octomap(const octomap::OcTree &tree, Variant variant) {
    std::vector<FclObjectPtr> boxes;
    for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
        if (!tree.isNodeOccupied(*it)) continue;
        boxes.push_back(std::make_unique<fcl::CollisionObjectd>(cell_geometry(it.getSize(), variant),
                                                                translation(it.getX(), it.getY(), it.getZ())));
    }
    return boxes;
}

std::unique_ptr<FclManager> manage_objects(const std::vector<FclObjectPtr> &objects) {
    std::vector<fcl::CollisionObjectd *> pointers;
    pointers.reserve(objects.size());
    for (const FclObjectPtr &object : objects) pointers.push_back(object.get());
    auto manager = std::make_unique<FclManager>();
    manager->registerObjects(pointers);
    manager->setup();
    return manager;
}

bool fcl_managers_collide(const FclManager &robot, FclManager &map) {
    FirstContact state;
    robot.collide(&map, &state, stop_at_first_contact);
    return state.done;
}

FclObjectPtr wrap_octree(const std::shared_ptr<const octomap::OcTree> &tree) {
    return std::make_unique<fcl::CollisionObjectd>(std::make_shared<fcl::OcTreed>(tree));
}

bool fcl_octree_collides(const FclManager &robot, fcl::CollisionObjectd &octree) {
    FirstContact state;
    robot.collide(&octree, &state, stop_at_first_contact);
    return state.done;
}

size_t count_fcl_colliding_objects(const FclObjectSet &objects, const fcl::CollisionObjectd &octree) {
    size_t colliding = 0;
    const fcl::CollisionRequestd request;
    for (const FclObjectPtr &object : objects.objects) {
        fcl::CollisionResultd result;
        if (fcl::collide(object.get(), &octree, request, result) > 0) ++colliding;
    }
    return colliding;
}

}  // namespace paper_tables
