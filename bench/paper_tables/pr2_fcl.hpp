// The PR2 on FCL's side: one fcl::CollisionObject per collision shape of
// the OctoProx link set (primitives as FCL shapes, meshes as
// BVHModel<OBBRSS> over the same triangles), in a dynamic AABB tree.
#pragma once

#include <memory>
#include <vector>

#include <octoprox/octoprox.h>

#include "fcl_pipelines.hpp"

namespace paper_tables {

class FclRobot {
public:
    // Built from the link set's shapes, at its current link poses.
    explicit FclRobot(const opx_linkset *links);

    // Moves every object to its link's pose (map frame) composed with the
    // shape's pose in the link, and refits the manager.  `link_poses` has
    // one pose per link of the set, as opx_linkset_set_poses takes them.
    void set_link_poses(const std::vector<opx_pose> &link_poses);

    FclManager &manager() { return *manager_; }
    size_t object_count() const { return objects_.size(); }
    // Object i (one per shape, in link then shape order) and its link.
    fcl::CollisionObjectd &object(size_t i) { return *objects_[i]; }
    uint32_t object_link(size_t i) const { return placements_[i].link; }

private:
    struct Placement {
        uint32_t link;
        fcl::Transform3d shape_in_link;
    };
    std::vector<FclObjectPtr> objects_;
    std::vector<Placement> placements_;  // one per object
    std::unique_ptr<FclManager> manager_;
};

// The pose of every link of the set, in link order.
std::vector<opx_pose> link_poses(const opx_linkset *links);

}  // namespace paper_tables
