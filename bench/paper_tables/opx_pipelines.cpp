#include "opx_pipelines.hpp"

namespace paper_tables {
namespace {

opx_shape primitive_shape(const SceneObject &object) {
    opx_shape shape = OPX_SHAPE_INIT;
    switch (object.kind) {
    case ObjectKind::kSphere:
        shape.kind = OPX_SHAPE_SPHERE;
        shape.radius = object.radius;
        break;
    case ObjectKind::kBox:
        shape.kind = OPX_SHAPE_BOX;
        for (int i = 0; i < 3; ++i) shape.size[i] = object.size[i];
        break;
    case ObjectKind::kCylinder:
        shape.kind = OPX_SHAPE_CYLINDER;
        shape.radius = object.radius;
        shape.length = object.length;
        break;
    }
    return shape;
}

// The library copies the mesh during the call, so a temporary will do.
void add_object_shape(opx_linkset *links, uint32_t link, const SceneObject &object, Variant variant) {
    if (variant == Variant::kPrimitives) {
        const opx_shape shape = primitive_shape(object);
        check_opx(opx_linkset_add_shape(links, link, &shape, nullptr), "opx_linkset_add_shape");
        return;
    }
    const TriangleMesh mesh = object_mesh(object);
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_MESH;
    shape.vertices = mesh.vertices.data();
    shape.vertex_count = mesh.vertex_count();
    shape.indices = mesh.indices.data();
    shape.triangle_count = mesh.triangle_count();
    check_opx(opx_linkset_add_shape(links, link, &shape, nullptr), "opx_linkset_add_shape (mesh)");
}

OpxLinksetPtr make_empty_linkset() {
    opx_linkset *raw = nullptr;
    check_opx(opx_linkset_create(&raw), "opx_linkset_create");
    return OpxLinksetPtr(raw);
}

}  // namespace

OpxQueryPtr make_query(int32_t engine, uint32_t refine_steps) {
    opx_query_options options = OPX_QUERY_OPTIONS_INIT;
    options.engine = engine;
    options.refine_steps = refine_steps;
    opx_query *raw = nullptr;
    check_opx(opx_query_create(&options, &raw), "opx_query_create");
    return OpxQueryPtr(raw);
}

OpxQueryPtr make_direct_query() { return make_query(OPX_ENGINE_DIRECT); }
OpxQueryPtr make_amortized_query() { return make_query(OPX_ENGINE_AMORTIZED); }

OpxLinksetPtr make_object_linkset(const std::vector<SceneObject> &objects, Variant variant) {
    OpxLinksetPtr links = make_empty_linkset();
    for (const SceneObject &object : objects) {
        uint32_t link = 0;
        check_opx(opx_linkset_add_link(links.get(), "object", &link), "opx_linkset_add_link");
        add_object_shape(links.get(), link, object, variant);
    }
    set_object_poses(links.get(), objects);
    return links;
}

void set_object_poses(opx_linkset *links, const std::vector<SceneObject> &objects) {
    std::vector<opx_pose> poses;
    poses.reserve(objects.size());
    for (const SceneObject &object : objects) poses.push_back(object.pose);
    check_opx(opx_linkset_set_poses(links, poses.data(), poses.size(), 0), "opx_linkset_set_poses");
}

bool opx_collides(opx_query *query, const opx_octree *tree, const opx_linkset *links) {
    opx_collision_result result = OPX_COLLISION_RESULT_INIT;
    check_opx(opx_query_collide(query, tree, links, nullptr, &result), "opx_query_collide");
    return result.collided != 0;
}

ObjectProbe::ObjectProbe() : query_(make_direct_query()) {}

bool ObjectProbe::collides(const opx_octree *tree, const SceneObject &object, Variant variant) {
    const OpxLinksetPtr links = make_object_linkset({object}, variant);
    return opx_collides(query_.get(), tree, links.get());
}

}  // namespace paper_tables
