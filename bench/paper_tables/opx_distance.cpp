#include "opx_distance.hpp"

#include <limits>

namespace paper_tables {

double opx_min_distance(opx_query *query, const opx_octree *tree, const opx_linkset *links) {
    opx_distance_result result = OPX_DISTANCE_RESULT_INIT;
    check_opx(opx_query_distance(query, tree, links, nullptr, &result), "opx_query_distance");
    return result.found != 0 ? result.distance : std::numeric_limits<double>::infinity();
}

OpxLinksetPtr make_sphere_linkset(double radius) {
    opx_linkset *raw = nullptr;
    check_opx(opx_linkset_create(&raw), "opx_linkset_create");
    OpxLinksetPtr links(raw);
    uint32_t link = 0;
    check_opx(opx_linkset_add_link(links.get(), "sphere", &link), "opx_linkset_add_link");
    opx_shape shape = OPX_SHAPE_INIT;
    shape.kind = OPX_SHAPE_SPHERE;
    shape.radius = radius;
    check_opx(opx_linkset_add_shape(links.get(), link, &shape, nullptr), "opx_linkset_add_shape");
    return links;
}

void move_single_link(opx_linkset *links, const std::array<double, 3> &position) {
    opx_pose pose = OPX_POSE_IDENTITY;
    for (int i = 0; i < 3; ++i) pose.position[i] = position[i];
    check_opx(opx_linkset_set_poses(links, &pose, 1, 0), "opx_linkset_set_poses");
}

OpxOctreePtr load_opx_octree(const std::string &path) {
    opx_octree *raw = nullptr;
    check_opx(opx_octree_load_file(path.c_str(), nullptr, &raw), "opx_octree_load_file");
    return OpxOctreePtr(raw);
}

}  // namespace paper_tables
