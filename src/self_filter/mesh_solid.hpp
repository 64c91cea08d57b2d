// A closed triangle mesh as the solid it bounds, grown by a ball: its
// points are those inside the mesh or within `radius` of a triangle.  The
// placed mesh's triangle tree (map frame) culls the triangles.
#pragma once

#include "robot/shape.hpp"

namespace octoprox {

// As grown_core_entry (solid_geometry.hpp) for the solid a closed mesh
// bounds grown by `radius`, whose boundary a ray from outside crosses
// first through a grown triangle: its faces and their tree
// (mesh_faces.hpp), in the frame `pose` (center, axes) places in the map
// frame.
double grown_faces_entry(const MeshFaces &faces, const Convex &pose, double radius, const Vec3 &origin,
                         const Vec3 &dir, double t_max);

// The shape must be a closed mesh, placed (PlacedShape::place_mesh).
class MeshSolid {
public:
    MeshSolid(const PlacedShape &mesh, double radius) : mesh_(mesh), radius_(radius) {}

    // Whether the grown solid holds `x`.
    bool holds(const Vec3 &x) const { return near_surface(x) || inside(x); }
    // Whether `x` lies inside the mesh (by the parity of a ray's crossings).
    bool inside(const Vec3 &x) const;
    // Whether a triangle lies within `radius` of `x`.
    bool near_surface(const Vec3 &x) const;
    // Whether a triangle touches the closed box.
    bool touches_box(const Aabb &box) const;

private:
    // Crossings of the ray from `x` along `dir` with the triangles; false
    // when the ray grazes an edge or a vertex (too close to call).
    bool count_crossings(const Vec3 &x, const Vec3 &dir, int &crossings) const;

    const PlacedShape &mesh_;
    double radius_;
};

}  // namespace octoprox
