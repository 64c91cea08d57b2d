#include "world/shape_region.hpp"

#include "narrowphase/narrow_phase.hpp"
#include "octree/octree_cell.hpp"

namespace octoprox {

ShapesRegion::ShapesRegion(std::vector<ShapeDef> shapes, const Pose &pose, double resolution)
    : resolution_(resolution) {
    defs_.reserve(shapes.size());
    placed_.resize(shapes.size());
    for (size_t i = 0; i < shapes.size(); ++i) {
        defs_.push_back(std::make_unique<ShapeDef>(std::move(shapes[i])));
        if (defs_.back()->kind == ShapeKind::kMesh) build_mesh_tree(*defs_.back());
        place_shape(*defs_.back(), pose, 0.0, true, placed_[i]);
        bounds_.grow(placed_[i].box);
    }
}

Cover ShapesRegion::cover(const CellKey &cube) const {
    const Aabb box = cell_box(cube, resolution_);
    const Aabb reach{box.lo - Vec3::Constant(kTouchTolerance), box.hi + Vec3::Constant(kTouchTolerance)};
    if (!reach.overlaps(bounds_)) return Cover::kNone;
    for (const PlacedShape &shape : placed_) {
        if (!reach.overlaps(shape.box) || !shape_may_touch(shape, box)) continue;
        if (cube.depth < kTreeDepth) return Cover::kPart;
        uint64_t tests = 0;
        if (shape_touches_cell(shape, box.center(), box.half_extent(), tests)) return Cover::kAll;
    }
    return Cover::kNone;
}

}  // namespace octoprox
