// The map cells a set of shapes occupies, for clearing them: a finest cell
// is in when one of the shapes touches its cube, exactly as a collision
// query decides that a link's shape touches a cell (narrow_phase.hpp, the
// same tolerance), so that after clearing them the shapes collide with no
// cell of the map.
#pragma once

#include "octree/region_edit.hpp"
#include "robot/shape.hpp"

#include <memory>
#include <vector>

namespace octoprox {

class ShapesRegion : public CubeRegion {
public:
    // `shapes` at their poses in the object frame, the object at `pose` in
    // the map frame; meshes get their triangle trees here.
    ShapesRegion(std::vector<ShapeDef> shapes, const Pose &pose, double resolution);
    Cover cover(const CellKey &cube) const override;

private:
    std::vector<std::unique_ptr<ShapeDef>> defs_;  // placed shapes point at them
    std::vector<PlacedShape> placed_;
    Aabb bounds_;  // of every placed shape
    double resolution_;
};

}  // namespace octoprox
