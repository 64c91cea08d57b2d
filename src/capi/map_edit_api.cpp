// C shims: clearing regions and shapes, decay and cropping, and the box
// of a bounded insert.
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "capi/shape_input.hpp"

#include "octree/region_edit.hpp"
#include "world/shape_region.hpp"

#include <cmath>

namespace octoprox::capi {

CellRange read_box(const double box_min[3], const double box_max[3], double resolution, const char *min_name,
                  const char *max_name) {
    require_pointer(box_min, min_name);
    require_pointer(box_max, max_name);
    for (int axis = 0; axis < 3; ++axis) {
        if (std::isnan(box_min[axis])) throw_invalid(format("%s[%d] is NaN", min_name, axis));
        if (std::isnan(box_max[axis])) throw_invalid(format("%s[%d] is NaN", max_name, axis));
        if (box_min[axis] > box_max[axis])
            throw_invalid(format("%s[%d] %g is above %s[%d] %g: the box is inverted", min_name, axis, box_min[axis],
                                 max_name, axis, box_max[axis]));
    }
    return cell_range_of_box(box_min, box_max, resolution);
}

namespace {

bool read_clear_target(int32_t to) {
    if (to != OPX_CELL_FREE && to != OPX_CELL_UNKNOWN)
        throw_invalid(format("to is %d; OPX_CELL_FREE (%d) or OPX_CELL_UNKNOWN (%d) is needed", to, OPX_CELL_FREE,
                             OPX_CELL_UNKNOWN));
    return to == OPX_CELL_FREE;
}

// The shapes of an object as opx_linkset_attach_object takes them; none
// is allowed here (nothing to clear).
std::vector<ShapeDef> read_object_shapes(const opx_shape *shapes, size_t count) {
    if (count > 0) require_pointer(shapes, "shapes");
    std::vector<ShapeDef> defs;
    defs.reserve(count);
    for (size_t i = 0; i < count; ++i) {
        try {
            defs.push_back(read_shape(&shapes[i]));
        } catch (const ApiError &error) {
            throw ApiError(error.status(), format("shapes[%zu]: %s", i, error.what()));
        }
    }
    return defs;
}

}  // namespace
}  // namespace octoprox::capi

using namespace octoprox;
using namespace octoprox::capi;

extern "C" {

OPX_API opx_status opx_octree_clear_region(opx_octree *tree, const double box_min[3], const double box_max[3],
                                           int32_t to) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        const CellRange box = read_box(box_min, box_max, tree->tree->params().resolution, "box_min", "box_max");
        const bool to_free = read_clear_target(to);
        for (int axis = 0; to_free && axis < 3; ++axis)
            if (!std::isfinite(box_min[axis]) || !std::isfinite(box_max[axis]))
                throw_invalid(format("box_min/box_max hold an infinite value on axis %d: a box cleared to "
                                     "OPX_CELL_FREE must be finite (its unknown cells become free too)",
                                     axis));
        if (!box.empty()) tree->tree->clear_region(CellRangeRegion(box, false), to_free);
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_clear_shapes(opx_octree *tree, const opx_shape *shapes, size_t shape_count,
                                           const opx_pose *pose, int32_t to) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        std::vector<ShapeDef> defs = read_object_shapes(shapes, shape_count);
        const Pose placed = pose == nullptr ? Pose() : read_pose(*pose, "pose");
        require_position_in_bounds(placed, "pose");
        const bool to_free = read_clear_target(to);
        if (defs.empty()) return OPX_OK;
        const ShapesRegion region(std::move(defs), placed, tree->tree->params().resolution);
        tree->tree->clear_region(region, to_free);
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_decay(opx_octree *tree, double amount) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        if (!(amount >= 0.0))
            throw_invalid(format("amount is %g; a decay is a log-odds amount >= 0", amount));
        tree->tree->decay(amount);
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_crop(opx_octree *tree, const double box_min[3], const double box_max[3]) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        const CellRange box = read_box(box_min, box_max, tree->tree->params().resolution, "box_min", "box_max");
        tree->tree->crop(box);
        return OPX_OK;
    });
}

}  // extern "C"
