// C shims: reading the map (classification, statistics, leaves).
#include "capi/checks.hpp"
#include "capi/handles.hpp"
#include "octree/traverse.hpp"

using namespace octoprox;
using namespace octoprox::capi;

namespace {

opx_cell_info cell_info_to_abi(const CellInfo &c) {
    opx_cell_info out = OPX_CELL_INFO_INIT;
    out.cell_class = c.cell_class;
    out.probability = c.probability;
    for (int axis = 0; axis < 3; ++axis) out.center[axis] = c.center[axis];
    out.size = c.size;
    out.depth = static_cast<uint32_t>(c.depth);
    return out;
}

opx_octree_stats stats_to_abi(const TreeStats &s, double resolution) {
    opx_octree_stats out = OPX_OCTREE_STATS_INIT;
    out.has_occupied = s.has_occupied ? 1 : 0;
    out.resolution = resolution;
    out.leaves_occupied = s.leaves[kOccupied];
    out.leaves_uncertain = s.leaves[kUncertain];
    out.leaves_free = s.leaves[kFree];
    out.inner_nodes = s.inner_nodes;
    out.memory_bytes = s.memory_bytes;
    out.leaves_with_extent = s.leaves_with_extent;
    for (int axis = 0; axis < 3; ++axis) {
        out.occupied_min[axis] = s.occupied_min[axis];
        out.occupied_max[axis] = s.occupied_max[axis];
        out.known_min[axis] = s.known_min[axis];
        out.known_max[axis] = s.known_max[axis];
    }
    return out;
}

// Visits the leaves in class_mask, writing the first `capacity` of them.
size_t copy_leaves(const SensorOctree &tree, uint32_t class_mask, opx_leaf *out, size_t capacity) {
    const OctreeView view = tree.view();
    const double res = tree.params().resolution;
    size_t count = 0;
    for_each_leaf(view, [&](OctreeView::NodeRef node, const CellKey &cell) {
        const float l = view.log_odds(node);
        const int cls = tree.classify_log_odds(l);
        if (!((class_mask >> cls) & 1u)) return;
        if (count < capacity) {
            opx_leaf &leaf = out[count];
            for (int axis = 0; axis < 3; ++axis) leaf.center[axis] = cell.center(axis, res);
            leaf.size = cell.size(res);
            leaf.probability = probability_from_log_odds(l);
            leaf.cell_class = cls;
            leaf.depth = static_cast<uint32_t>(cell.depth);
        }
        ++count;
    });
    return count;
}

}  // namespace

extern "C" {

OPX_API opx_status opx_cell_info_init(opx_cell_info *info, size_t size) {
    return init_struct(__func__, info, size, opx_cell_info(OPX_CELL_INFO_INIT), "info");
}

OPX_API opx_status opx_octree_stats_init(opx_octree_stats *stats, size_t size) {
    return init_struct(__func__, stats, size, opx_octree_stats(OPX_OCTREE_STATS_INIT), "stats");
}

OPX_API opx_status opx_octree_classify(const opx_octree *tree, const double point[3],
                                       opx_cell_info *out) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        require_pointer(point, "point");
        require_out_struct(out, "out");
        const Vec3 p(point[0], point[1], point[2]);
        for (int axis = 0; axis < 3; ++axis) {
            if (!std::isfinite(point[axis]))
                throw_invalid(format("point[%d] is %g, not a finite number", axis, point[axis]));
        }
        if (!tree->tree->contains(p))
            throw_invalid(format("point (%g, %g, %g) lies outside the map cube (+-%g m)", p.x(),
                                 p.y(), p.z(), kKeyCenter * tree->tree->params().resolution));
        write_versioned(out, cell_info_to_abi(tree->tree->classify(p)), "out");
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_get_stats(const opx_octree *tree, opx_octree_stats *out) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        require_out_struct(out, "out");
        write_versioned(out, stats_to_abi(tree->tree->stats(), tree->tree->params().resolution), "out");
        return OPX_OK;
    });
}

OPX_API opx_status opx_octree_get_leaves(const opx_octree *tree, uint32_t class_mask,
                                         opx_leaf *out_leaves, size_t capacity,
                                         size_t *out_count) {
    return guard(__func__, [&] {
        require_pointer(tree, "tree");
        require_pointer(out_count, "out_count");
        if (capacity > 0) require_pointer(out_leaves, "out_leaves");
        if ((class_mask & ~OPX_MASK_ALL_KNOWN) != 0)
            throw_invalid(format("class_mask 0x%x has bits other than OPX_MASK_FREE, "
                                 "OPX_MASK_UNCERTAIN and OPX_MASK_OCCUPIED",
                                 class_mask));
        *out_count = copy_leaves(*tree->tree, class_mask, out_leaves, capacity);
        if (*out_count > capacity)
            throw ApiError(OPX_ERROR_BUFFER_TOO_SMALL,
                           format("out_leaves holds %zu leaves, %zu are needed (see *out_count)",
                                  capacity, *out_count));
        return OPX_OK;
    });
}

}  // extern "C"
