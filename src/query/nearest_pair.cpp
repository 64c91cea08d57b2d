#include "query/nearest_pair.hpp"

#include "narrowphase/shape_penetration.hpp"

#include <algorithm>

namespace octoprox {

bool nearer_pair(const PlacedShape &shape, const Aabb &cell, double bound, bool signed_distance,
                 ShapeCellDistance &out, uint64_t &narrow_tests) {
    // Signed and in contact (bound <= 0), a touching cell (distance 0) must
    // still be found to be measured by its penetration.
    const double limit = signed_distance ? std::max(bound, 1e-300) : bound;
    const Vec3 center = cell.center(), half = cell.half_extent();
    if (!shape_cell_distance(shape, center, half, limit, out, narrow_tests)) return false;
    if (signed_distance && out.distance <= 0.0) {
        const ShapePenetration p = shape_penetration(shape, center, half);
        out.distance = -p.depth, out.on_shape = p.on_link, out.on_cell = p.on_cell;
    }
    return out.distance < bound;
}

bool keep_if_nearer(const PlacedShape &shape, const ShapeCellDistance &pair, DistanceOutcome &best) {
    if (best.found && !(pair.distance < best.distance)) return false;
    best.found = true;
    best.distance = pair.distance;
    best.on_link = pair.on_shape;
    best.on_cell = pair.on_cell;
    best.link = shape.link, best.shape = shape.shape, best.attached = shape.attached;
    return true;
}

}  // namespace octoprox
