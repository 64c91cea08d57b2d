// The OctoProx side of the tables: the objects as one link set (one link
// per object, one shape per link) queried directly against the octree.
// There is no per-frame preprocessing: T_{1,1} = T_{1,2} = 0.
#pragma once

#include <memory>
#include <vector>

#include <octoprox/octoprox.h>

#include "scene.hpp"

namespace paper_tables {

struct LinksetDeleter {
    void operator()(opx_linkset *links) const { opx_linkset_destroy(links); }
};
struct QueryDeleter {
    void operator()(opx_query *query) const { opx_query_destroy(query); }
};
using OpxLinksetPtr = std::unique_ptr<opx_linkset, LinksetDeleter>;
using OpxQueryPtr = std::unique_ptr<opx_query, QueryDeleter>;

// A query context of the given engine (OPX_ENGINE_DIRECT, ...) and
// refinement paths per query (amortized; 1 is the library's default), and
// the two contexts the tables use.
OpxQueryPtr make_query(int32_t engine, uint32_t refine_steps = 1);
OpxQueryPtr make_direct_query();
OpxQueryPtr make_amortized_query();

// A link set with one link per object, holding its primitive (variant a)
// or its mesh (variant b), at the objects' poses.
OpxLinksetPtr make_object_linkset(const std::vector<SceneObject> &objects, Variant variant);

// Moves every link to its object's pose (one opx_linkset_set_poses call).
void set_object_poses(opx_linkset *links, const std::vector<SceneObject> &objects);

// One collision query with the default request (max_contacts 1: stop at
// the first contact); true when some link touches an occupied cell.
bool opx_collides(opx_query *query, const opx_octree *tree, const opx_linkset *links);

// Tests objects one at a time (each as a one-link set), for building the
// collision-free scene.
class ObjectProbe {
public:
    ObjectProbe();
    bool collides(const opx_octree *tree, const SceneObject &object, Variant variant);

private:
    OpxQueryPtr query_;
};

}  // namespace paper_tables
