// The robot at a frame's capture time as the insert's ray clip
// (octree/ray_clip.hpp): each link shape's solid grown by its padding plus
// the frame's robot_padding, found from the sensor by direction bins
// (direction_bins.hpp) and tested exactly (solid_geometry.hpp,
// mesh_solid.hpp).  The semantics are octree.h's ("The robot in its own
// frame").
#pragma once

#include "octree/ray_clip.hpp"
#include "robot/linkset.hpp"
#include "self_filter/direction_bins.hpp"

#include <memory>
#include <vector>

namespace octoprox {

// One enabled shape's solid.
struct FilterSolid {
    const PlacedShape *shape = nullptr;
    Convex core;               // every solid but a closed mesh (an open mesh: its vertices' hull)
    bool closed_mesh = false;  // the mesh's triangles bound the solid
    std::shared_ptr<const MeshFaces> faces;  // a closed mesh's (ShapeDef::faces)
    std::shared_ptr<const MeshFaces> hull_faces;  // a hull's, when it spans a volume (ShapeDef::hull_faces)
    double radius = 0.0;       // the ball grown onto the core: inflation plus robot_padding
    double solid_radius = 0.0; // the same without any padding (the unpadded solid)
    bool holds_origin = false; // the grown solid holds the sensor: it shadows nothing
    // The core's box in its own frame (core.center, core.axes), grown by
    // `radius`: a ray that misses it misses the solid.  Empty: not used.
    Aabb local_box;

    // Whether the solid grown by `grow` holds `x`.
    bool holds(const Vec3 &x, double grow) const;
    // Whether the segment origin + t * dir, t in [0, t_max], meets local_box.
    bool may_meet(const Vec3 &origin, const Vec3 &dir, double t_max) const;
    // As grown_core_entry for the padded solid.
    double entry(const Vec3 &origin, const Vec3 &dir, double t_max) const;
};

class PaddedRobot final : public RayClip {
public:
    // Reads `robot`'s placed shapes (placing its meshes); keeps pointers
    // into it, so the link set must outlive this and not change.
    PaddedRobot(const LinkSet &robot, double robot_padding, const Vec3 &origin);

    RayCut cut(const Vec3 &end, bool end_is_point) const override;
    const std::vector<FilterSolid> &solids() const { return solids_; }

private:
    // Up to this many candidate solids a ray are taken nearest first.
    static constexpr size_t kOrdered = 64;
    struct Candidate {
        double t0;
        uint32_t index;
    };
    void consider(uint32_t index, const Vec3 &end, const Vec3 &dir, bool end_is_point, double &best_t, bool &entered,
                  bool &on_robot) const;

    Vec3 origin_;
    std::vector<FilterSolid> solids_;
    std::vector<std::vector<Vec3>> hulls_;  // the hull solids' placed points, which their cores point into
    std::vector<Ball> balls_;  // per solid: a ball holding the padded solid
    DirectionBins bins_;
};

}  // namespace octoprox
